// The values of POV-Ray expressions and identifiers: floats, vectors of 2 to 5 components (a
// colour is the 5-vector red, green, blue, filter, transmit), strings and arrays, with
// POV-Ray's promotion of a float to a vector in mixed arithmetic.
#pragma once

#include <array>
#include <cstddef>
#include <memory>
#include <string>
#include <variant>
#include <vector>

namespace glint {

struct PovVector {
    std::array<double, 5> c{};
    int size = 3;  // 2 (uv), 3, 4 or 5 (a colour)

    double operator[](int i) const { return c[std::size_t(i)]; }
    double& operator[](int i) { return c[std::size_t(i)]; }
    // A float as a vector of `n` equal components.
    static PovVector of(double value, int n);
};

struct PovArray;
// A declared object, texture, pigment, finish, interior or transform (pov_items.h).
struct PovItemRef;

using PovValue = std::variant<double, PovVector, std::string, std::shared_ptr<PovArray>,
                              std::shared_ptr<const PovItemRef>>;

// A fixed-size array of one or more dimensions; an element is empty until assigned.
struct PovArray {
    std::vector<std::size_t> sizes;                   // the dimensions, outermost first
    std::vector<std::shared_ptr<PovValue>> elements;  // row-major; null: not assigned yet
};

// A number as messages show it: the shortest text that reads back the same.
std::string format_pov_number(double value);

// "a float", "a vector", "a string", "an array", "an object": for messages.
const char* kind_of(const PovValue& value);

// Componentwise arithmetic with promotion: a float meets a vector as a vector of its size, and a
// shorter vector is widened with zeros (as POV-Ray does). op is one of + - * /.
PovVector combine(const PovVector& a, const PovVector& b, char op);

}  // namespace glint
