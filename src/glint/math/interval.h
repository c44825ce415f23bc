// A closed range of ray parameters [min, max]; the part of a ray a query looks at. It travels
// beside the Ray (which has no range of its own): traversal narrows it to the nearest hit so far.
#pragma once

#include <limits>

namespace glint {

inline constexpr float kInfinity = std::numeric_limits<float>::infinity();

struct Interval {
    float min = 0;
    float max = kInfinity;

    constexpr bool contains(float t) const { return min <= t && t <= max; }
    constexpr bool is_empty() const { return !(min <= max); }
};

}  // namespace glint
