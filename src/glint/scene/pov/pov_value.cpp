#include "glint/scene/pov/pov_value.h"

#include <algorithm>
#include <charconv>

namespace glint {

PovVector PovVector::of(double value, int n) {
    PovVector v;
    v.size = n;
    for (int i = 0; i < n; ++i) v[i] = value;
    return v;
}

std::string format_pov_number(double value) {
    char buffer[64];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

const char* kind_of(const PovValue& value) {
    switch (value.index()) {
        case 0:
            return "a float";
        case 1:
            return "a vector";
        case 2:
            return "a string";
        case 3:
            return "an array";
        default:
            return "an object or texture";
    }
}

PovVector combine(const PovVector& a, const PovVector& b, char op) {
    PovVector r;
    r.size = std::max(a.size, b.size);
    for (int i = 0; i < r.size; ++i) {
        const double x = a[i], y = b[i];
        switch (op) {
            case '+':
                r[i] = x + y;
                break;
            case '-':
                r[i] = x - y;
                break;
            case '*':
                r[i] = x * y;
                break;
            default:
                r[i] = x / y;
                break;
        }
    }
    return r;
}

}  // namespace glint
