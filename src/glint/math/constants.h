// Mathematical constants and angle conversions.
#pragma once

namespace glint {

inline constexpr float kPi = 3.14159265358979323846f;

constexpr float radians(float degrees) { return degrees * (kPi / 180); }
constexpr float degrees(float radians) { return radians * (180 / kPi); }

}  // namespace glint
