// An allowed range of numbers, as scene keys declare them (entity_schema.h) and readers check them.
#pragma once

#include <limits>
#include <string>

namespace glint {

// Infinite ends are open.
struct Range {
    double min = -std::numeric_limits<double>::infinity();
    double max = std::numeric_limits<double>::infinity();
    bool min_open = false;
    bool max_open = false;

    bool contains(double v) const;
    std::string describe() const;  // "> 0", ">= 0", "in [0, 1]", "in (0, 180)"
    bool is_any() const {
        return min == -std::numeric_limits<double>::infinity() &&
               max == std::numeric_limits<double>::infinity();
    }
};

inline constexpr Range kAnyNumber{};
inline constexpr Range kPositive{0, std::numeric_limits<double>::infinity(), true};
inline constexpr Range kNonNegative{0};
inline constexpr Range kUnitInterval{0, 1};

}  // namespace glint
