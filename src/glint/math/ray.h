// A ray P(t) = origin + t * direction. Queries pair it with an Interval of t.
#pragma once

#include "glint/math/vector.h"

namespace glint {

// Contract: world-space rays carry a unit-length direction, so t is a distance (the lecture
// notes' |R| = 1). Shapes rely on it.
struct Ray {
    Point3 origin;
    Vector3 direction;

    constexpr Point3 at(float t) const { return origin + direction * t; }
};

}  // namespace glint
