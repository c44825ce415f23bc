// Vectors, points and normals in 3D (and 2D for image and texture coordinates).
// They are distinct types so that the compiler rejects meaningless sums such as point + point.
#pragma once

#include <algorithm>
#include <cmath>

namespace glint {

struct Vector3 {
    float x = 0, y = 0, z = 0;

    constexpr Vector3() = default;
    constexpr Vector3(float x_, float y_, float z_) : x(x_), y(y_), z(z_) {}

    constexpr float operator[](int axis) const { return axis == 0 ? x : axis == 1 ? y : z; }
    constexpr Vector3 operator-() const { return {-x, -y, -z}; }
    constexpr Vector3 operator+(Vector3 v) const { return {x + v.x, y + v.y, z + v.z}; }
    constexpr Vector3 operator-(Vector3 v) const { return {x - v.x, y - v.y, z - v.z}; }
    constexpr Vector3 operator*(float s) const { return {x * s, y * s, z * s}; }
    constexpr Vector3 operator/(float s) const { return *this * (1 / s); }
    constexpr Vector3& operator+=(Vector3 v) { return *this = *this + v; }
    constexpr bool operator==(const Vector3&) const = default;
};

constexpr Vector3 operator*(float s, Vector3 v) { return v * s; }

// A position. Points differ by vectors; they are never added to each other.
struct Point3 {
    float x = 0, y = 0, z = 0;

    constexpr Point3() = default;
    constexpr Point3(float x_, float y_, float z_) : x(x_), y(y_), z(z_) {}

    constexpr float operator[](int axis) const { return axis == 0 ? x : axis == 1 ? y : z; }
    constexpr Point3 operator+(Vector3 v) const { return {x + v.x, y + v.y, z + v.z}; }
    constexpr Point3 operator-(Vector3 v) const { return {x - v.x, y - v.y, z - v.z}; }
    constexpr Vector3 operator-(Point3 p) const { return {x - p.x, y - p.y, z - p.z}; }
    constexpr bool operator==(const Point3&) const = default;
};

// A surface normal. Kept apart from Vector3 because transforms map it by the inverse transpose.
struct Normal3 {
    float x = 0, y = 0, z = 0;

    constexpr Normal3() = default;
    constexpr Normal3(float x_, float y_, float z_) : x(x_), y(y_), z(z_) {}
    constexpr explicit Normal3(Vector3 v) : x(v.x), y(v.y), z(v.z) {}

    constexpr float operator[](int axis) const { return axis == 0 ? x : axis == 1 ? y : z; }
    constexpr Normal3 operator-() const { return {-x, -y, -z}; }
    constexpr bool operator==(const Normal3&) const = default;
};

constexpr Vector3 to_vector(Normal3 n) { return {n.x, n.y, n.z}; }
constexpr Vector3 to_vector(Point3 p) { return {p.x, p.y, p.z}; }
constexpr Point3 to_point(Vector3 v) { return {v.x, v.y, v.z}; }

constexpr float dot(Vector3 a, Vector3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
constexpr float dot(Normal3 n, Vector3 v) { return n.x * v.x + n.y * v.y + n.z * v.z; }
constexpr float dot(Vector3 v, Normal3 n) { return dot(n, v); }
constexpr float dot(Normal3 a, Normal3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

constexpr Vector3 cross(Vector3 a, Vector3 b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

constexpr float length_squared(Vector3 v) { return dot(v, v); }
inline float length(Vector3 v) { return std::sqrt(dot(v, v)); }
inline float distance(Point3 a, Point3 b) { return length(a - b); }
inline Vector3 normalize(Vector3 v) { return v / length(v); }
inline Normal3 normalize(Normal3 n) { return Normal3(normalize(to_vector(n))); }

// The normal turned to lie on the same side of the surface as v.
constexpr Normal3 face_forward(Normal3 n, Vector3 v) { return dot(n, v) < 0 ? -n : n; }

constexpr Vector3 min(Vector3 a, Vector3 b) {
    return {std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)};
}
constexpr Vector3 max(Vector3 a, Vector3 b) {
    return {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)};
}
constexpr Point3 min(Point3 a, Point3 b) {
    return {std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)};
}
constexpr Point3 max(Point3 a, Point3 b) {
    return {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)};
}
constexpr float max_component(Vector3 v) { return std::max({v.x, v.y, v.z}); }
inline Vector3 abs(Vector3 v) { return {std::abs(v.x), std::abs(v.y), std::abs(v.z)}; }

inline bool is_finite(Vector3 v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
inline bool is_finite(Point3 p) { return is_finite(to_vector(p)); }

// Two unit vectors that complete the unit vector n to a right-handed orthonormal basis
// (Duff et al. 2017, "Building an Orthonormal Basis, Revisited").
inline void orthonormal_basis(Vector3 n, Vector3& s, Vector3& t) {
    const float sign = std::copysign(1.0f, n.z);
    const float a = -1 / (sign + n.z);
    const float b = n.x * n.y * a;
    s = {1 + sign * n.x * n.x * a, sign * b, -sign * n.x};
    t = {b, sign + n.y * n.y * a, -n.y};
}

struct Point2 {
    float x = 0, y = 0;
    constexpr bool operator==(const Point2&) const = default;
};

}  // namespace glint
