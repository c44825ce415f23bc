// Directions of the secondary rays of Whitted's model: mirror reflection and refraction.
#pragma once

#include <cmath>
#include <optional>

#include "glint/math/vector.h"

namespace glint {

// Mirror reflection R = D - 2 (D.N) N of the incoming direction D about the unit normal N.
constexpr Vector3 reflect(Vector3 d, Normal3 n) { return d - 2 * dot(d, n) * to_vector(n); }

// Snell's law with total internal reflection (Whitted 1980). d is the unit incoming direction,
// n the unit normal on the incoming side (d.n <= 0), eta = n_incident / n_transmitted.
// Returns nothing when sin^2(theta_t) > 1: all energy goes to the reflected ray.
inline std::optional<Vector3> refract(Vector3 d, Normal3 n, float eta) {
    const float cos_i = -dot(d, n);
    const float sin2_t = eta * eta * (1 - cos_i * cos_i);
    if (sin2_t > 1) return std::nullopt;
    const float cos_t = std::sqrt(1 - sin2_t);
    return eta * d + (eta * cos_i - cos_t) * to_vector(n);
}

}  // namespace glint
