// Directions of the secondary rays of Whitted's model: mirror reflection and refraction.
#pragma once

#include <algorithm>
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

// Fresnel's reflectance of a dielectric for unpolarised light: the mean of the s and p
// polarisations' squared amplitude ratios, cos_i the cosine of the angle of incidence (>= 0),
// eta = n_incident / n_transmitted; 1 on total internal reflection.
inline float fresnel_dielectric(float cos_i, float eta) {
    cos_i = std::clamp(cos_i, 0.0f, 1.0f);
    const float sin2_t = eta * eta * (1 - cos_i * cos_i);
    if (sin2_t >= 1) return 1;
    const float cos_t = std::sqrt(1 - sin2_t);
    const float s = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    const float p = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    return (s * s + p * p) / 2;
}

}  // namespace glint
