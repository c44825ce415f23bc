// 4x4 matrix arithmetic (products and Gauss-Jordan inversion in double) and the named
// transforms with their inverses; points, vectors, normals and boxes transformed.
#include "glint/math/transform.h"

#include <algorithm>
#include <cmath>

#include "glint/math/constants.h"

namespace glint {

Matrix4 operator*(const Matrix4& a, const Matrix4& b) {
    Matrix4 r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            double sum = 0;
            for (int k = 0; k < 4; ++k) sum += double(a.m[i][k]) * b.m[k][j];
            r.m[i][j] = static_cast<float>(sum);
        }
    return r;
}

Matrix4 transpose(const Matrix4& a) {
    Matrix4 r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) r.m[i][j] = a.m[j][i];
    return r;
}

// Gauss-Jordan elimination with partial pivoting, in double precision.
std::optional<Matrix4> inverse(const Matrix4& a) {
    double w[4][8];
    double scale = 0;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            w[i][j] = a.m[i][j];
            w[i][j + 4] = i == j ? 1 : 0;
            scale = std::max(scale, std::abs(w[i][j]));
        }
    if (!(scale > 0) || !std::isfinite(scale)) return std::nullopt;
    for (int col = 0; col < 4; ++col) {
        int pivot = col;
        for (int row = col + 1; row < 4; ++row)
            if (std::abs(w[row][col]) > std::abs(w[pivot][col])) pivot = row;
        if (std::abs(w[pivot][col]) <= 1e-12 * scale) return std::nullopt;
        if (pivot != col)
            for (int j = 0; j < 8; ++j) std::swap(w[pivot][j], w[col][j]);
        const double inv_pivot = 1 / w[col][col];
        for (int j = 0; j < 8; ++j) w[col][j] *= inv_pivot;
        for (int row = 0; row < 4; ++row) {
            if (row == col) continue;
            const double f = w[row][col];
            for (int j = 0; j < 8; ++j) w[row][j] -= f * w[col][j];
        }
    }
    Matrix4 r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) r.m[i][j] = static_cast<float>(w[i][j + 4]);
    return r;
}

std::optional<Transform> Transform::from_matrix(const Matrix4& m) {
    const auto inv = glint::inverse(m);
    if (!inv) return std::nullopt;
    return Transform(m, *inv);
}

Transform Transform::translate(Vector3 d) {
    Matrix4 m = Matrix4::identity(), inv = Matrix4::identity();
    m.m[0][3] = d.x, m.m[1][3] = d.y, m.m[2][3] = d.z;
    inv.m[0][3] = -d.x, inv.m[1][3] = -d.y, inv.m[2][3] = -d.z;
    return {m, inv};
}

Transform Transform::scale(float sx, float sy, float sz) {
    Matrix4 m = Matrix4::identity(), inv = Matrix4::identity();
    m.m[0][0] = sx, m.m[1][1] = sy, m.m[2][2] = sz;
    inv.m[0][0] = 1 / sx, inv.m[1][1] = 1 / sy, inv.m[2][2] = 1 / sz;
    return {m, inv};
}

// Rodrigues' rotation formula as a matrix; a rotation's inverse is its transpose.
Transform Transform::rotate(Vector3 axis, float angle_degrees) {
    const Vector3 a = normalize(axis);
    const double theta = double(angle_degrees) * kPi / 180;
    const double s = std::sin(theta), c = std::cos(theta), t = 1 - c;
    Matrix4 m = Matrix4::identity();
    m.m[0][0] = static_cast<float>(t * a.x * a.x + c);
    m.m[0][1] = static_cast<float>(t * a.x * a.y - s * a.z);
    m.m[0][2] = static_cast<float>(t * a.x * a.z + s * a.y);
    m.m[1][0] = static_cast<float>(t * a.x * a.y + s * a.z);
    m.m[1][1] = static_cast<float>(t * a.y * a.y + c);
    m.m[1][2] = static_cast<float>(t * a.y * a.z - s * a.x);
    m.m[2][0] = static_cast<float>(t * a.x * a.z - s * a.y);
    m.m[2][1] = static_cast<float>(t * a.y * a.z + s * a.x);
    m.m[2][2] = static_cast<float>(t * a.z * a.z + c);
    return {m, transpose(m)};
}

Point3 Transform::operator()(Point3 p) const {
    const auto& m = m_.m;
    const float x = m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z + m[0][3];
    const float y = m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z + m[1][3];
    const float z = m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z + m[2][3];
    const float w = m[3][0] * p.x + m[3][1] * p.y + m[3][2] * p.z + m[3][3];
    return w == 1 ? Point3{x, y, z} : Point3{x / w, y / w, z / w};
}

Vector3 Transform::operator()(Vector3 v) const {
    const auto& m = m_.m;
    return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z,
            m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
            m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
}

Normal3 Transform::operator()(Normal3 n) const {
    const auto& inv = inv_.m;
    return {inv[0][0] * n.x + inv[1][0] * n.y + inv[2][0] * n.z,
            inv[0][1] * n.x + inv[1][1] * n.y + inv[2][1] * n.z,
            inv[0][2] * n.x + inv[1][2] * n.y + inv[2][2] * n.z};
}

Bounds3 Transform::operator()(const Bounds3& b) const {
    if (b.is_empty()) return b;
    const auto& m = m_.m;
    if (!b.is_finite() && m[3][0] == 0 && m[3][1] == 0 && m[3][2] == 0 && m[3][3] == 1) {
        // Unbounded along an axis, affine: each axis of the result is the translation plus, for
        // each axis of the box, the entry times the box's extent along it (Arvo, Graphics Gems
        // 1990). An unbounded axis stays unbounded where the entry is not zero and adds nothing
        // where it is (the corners would multiply infinity by zero), or is only rounding's zero
        // (cos 90 degrees in float), 1e-6 of the row's largest entry. A finite box takes its
        // corners, so that it holds each corner exactly as a point transforms.
        const float lows[3] = {b.min.x, b.min.y, b.min.z}, highs[3] = {b.max.x, b.max.y, b.max.z};
        float lo[3], hi[3];
        for (int j = 0; j < 3; ++j) {
            const auto& row = m[std::size_t(j)];
            const float largest = std::max({std::abs(row[0]), std::abs(row[1]), std::abs(row[2])});
            lo[j] = hi[j] = row[3];
            for (int i = 0; i < 3; ++i) {
                const float e = row[std::size_t(i)];
                const bool unbounded = std::isinf(lows[i]) || std::isinf(highs[i]);
                if (e == 0 || (unbounded && std::abs(e) <= 1e-6f * largest)) continue;
                const float a = e * lows[i], c = e * highs[i];
                lo[j] += std::min(a, c);
                hi[j] += std::max(a, c);
            }
        }
        return {{lo[0], lo[1], lo[2]}, {hi[0], hi[1], hi[2]}};
    }
    Bounds3 r;
    for (int corner = 0; corner < 8; ++corner) {
        const Point3 p{corner & 1 ? b.max.x : b.min.x, corner & 2 ? b.max.y : b.min.y,
                       corner & 4 ? b.max.z : b.min.z};
        r = merge(r, (*this)(p));
    }
    return r;
}

Transform operator*(const Transform& a, const Transform& b) {
    return {a.matrix() * b.matrix(), b.inverse_matrix() * a.inverse_matrix()};
}

}  // namespace glint
