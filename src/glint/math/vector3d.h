// Double-precision vectors, for intermediate ray-shape algebra that cancels badly in float.
#pragma once

#include "glint/math/vector.h"

namespace glint {

// For the round shapes, whose quadratics and quartics cancel badly in float near tangency and
// for long thin shapes.
struct Vector3d {
    double x = 0, y = 0, z = 0;

    constexpr Vector3d() = default;
    constexpr Vector3d(double x_, double y_, double z_) : x(x_), y(y_), z(z_) {}
    constexpr explicit Vector3d(Vector3 v) : x(v.x), y(v.y), z(v.z) {}
    constexpr explicit Vector3d(Point3 p) : x(p.x), y(p.y), z(p.z) {}

    constexpr Vector3d operator+(Vector3d v) const { return {x + v.x, y + v.y, z + v.z}; }
    constexpr Vector3d operator-(Vector3d v) const { return {x - v.x, y - v.y, z - v.z}; }
    constexpr Vector3d operator*(double s) const { return {x * s, y * s, z * s}; }
    constexpr Vector3 to_float() const {
        return {static_cast<float>(x), static_cast<float>(y), static_cast<float>(z)};
    }
};
constexpr double dot(Vector3d a, Vector3d b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
constexpr Vector3d cross(Vector3d a, Vector3d b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

}  // namespace glint
