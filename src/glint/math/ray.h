// A ray P(t) = origin + t * direction, at a moment of time and, when split, of one wavelength. By
// design it holds no t range of its own: every query takes the ray and an Interval of t beside it
// (as pbrt-v4 passes tMax beside its Ray), so one ray serves closest-hit, shadow and
// shrinking-range queries without being copied or mutated.
#pragma once

#include "glint/math/vector.h"

namespace glint {

// Contract: world-space rays carry a unit-length direction, so t is a distance (the lecture
// notes' |R| = 1). Shapes rely on it.
struct Ray {
    Point3 origin;
    Vector3 direction;
    // When the ray is traced, in the camera's shutter interval: moving shapes take their place
    // at that time.
    float time = 0;
    // The wavelength the ray carries, in nanometres, once a dispersive surface has split it;
    // 0 for a ray that carries every wavelength (RGB).
    float wavelength = 0;

    constexpr Point3 at(float t) const { return origin + direction * t; }
};

// Rays traced together as one packet, at most (one to a lane of an eight-wide SIMD register).
inline constexpr int kRayPacketSize = 8;

}  // namespace glint
