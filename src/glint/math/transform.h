// Affine transforms as 4x4 matrices that carry their inverse. A transform is named by the
// spaces it maps: world_from_object takes object-space coordinates to world space.
#pragma once

#include <array>
#include <optional>

#include "glint/math/bounds.h"
#include "glint/math/ray.h"
#include "glint/math/vector.h"

namespace glint {

struct Matrix4 {
    std::array<std::array<float, 4>, 4> m{};  // m[row][column]

    static constexpr Matrix4 identity() {
        Matrix4 r;
        for (int i = 0; i < 4; ++i) r.m[i][i] = 1;
        return r;
    }
    constexpr bool operator==(const Matrix4&) const = default;
};

Matrix4 operator*(const Matrix4& a, const Matrix4& b);
Matrix4 transpose(const Matrix4& a);
// Nothing when the matrix is singular (or nearly so, relative to its scale).
std::optional<Matrix4> inverse(const Matrix4& a);

class Transform {
public:
    Transform() = default;
    // The caller guarantees that inv is the inverse of m.
    Transform(const Matrix4& m, const Matrix4& inv) : m_(m), inv_(inv) {}

    // Nothing when the matrix has no inverse.
    static std::optional<Transform> from_matrix(const Matrix4& m);
    static Transform translate(Vector3 delta);
    // Zero factors have no inverse: callers validate them first.
    static Transform scale(float sx, float sy, float sz);
    // Right-handed rotation by angle_degrees about the (not necessarily unit) axis.
    static Transform rotate(Vector3 axis, float angle_degrees);

    const Matrix4& matrix() const { return m_; }
    const Matrix4& inverse_matrix() const { return inv_; }
    Transform inverse() const { return {inv_, m_}; }

    Point3 operator()(Point3 p) const;
    Vector3 operator()(Vector3 v) const;
    // Normals map by the inverse transpose so they stay perpendicular to the surface.
    Normal3 operator()(Normal3 n) const;
    // The direction is transformed as a vector, not renormalised; time and wavelength stay.
    Ray operator()(const Ray& r) const {
        return {(*this)(r.origin), (*this)(r.direction), r.time, r.wavelength};
    }
    Bounds3 operator()(const Bounds3& b) const;

    bool operator==(const Transform&) const = default;

private:
    Matrix4 m_ = Matrix4::identity();
    Matrix4 inv_ = Matrix4::identity();
};

// Applies b first, then a: (a * b)(p) == a(b(p)).
Transform operator*(const Transform& a, const Transform& b);

}  // namespace glint
