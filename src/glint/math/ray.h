// A ray P(t) = origin + t * direction. By design it holds no t range of its own: every query
// takes the ray and an Interval of t beside it (as pbrt-v4 passes tMax beside its Ray), so one
// ray serves closest-hit, shadow and shrinking-range queries without being copied or mutated.
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
