#include "glint/scene/schema/value_range.h"

#include <charconv>
#include <cmath>

namespace glint {

namespace {

std::string shortest(double value) {
    char buffer[64];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

}  // namespace

bool Range::contains(double v) const {
    const bool above = min_open ? v > min : v >= min;
    const bool below = max_open ? v < max : v <= max;
    return above && below;
}

std::string Range::describe() const {
    if (std::isinf(max)) return (min_open ? "> " : ">= ") + shortest(min);
    return std::string("in ") + (min_open ? "(" : "[") + shortest(min) + ", " + shortest(max) +
           (max_open ? ")" : "]");
}

}  // namespace glint
