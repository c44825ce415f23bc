// Quaternion conversions and slerp, computed in double and rounded to float once at the end.
#include "glint/math/quaternion.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace glint {
namespace {

// (x, y, z, w) in double.
using Quat4 = std::array<double, 4>;

Quat4 widen(Quaternion q) { return {q.v.x, q.v.y, q.v.z, q.w}; }

Quaternion narrow(const Quat4& q) { return {{float(q[0]), float(q[1]), float(q[2])}, float(q[3])}; }

double dot4(const Quat4& a, const Quat4& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
}

Quat4 unit(Quat4 q) {
    const double inv = 1 / std::sqrt(dot4(q, q));
    for (double& c : q) c *= inv;
    return q;
}

// Half the angle between unit quaternions a and b on the 3-sphere, from the chord lengths
// |a - b| = 2 sin(alpha/2) and |a + b| = 2 cos(alpha/2): accurate for all angles.
double half_arc(const Quat4& a, const Quat4& b) {
    double difference = 0, sum = 0;
    for (int i = 0; i < 4; ++i) {
        difference += (a[i] - b[i]) * (a[i] - b[i]);
        sum += (a[i] + b[i]) * (a[i] + b[i]);
    }
    return std::atan2(std::sqrt(difference), std::sqrt(sum));
}

// b, negated if needed to lie in a's hemisphere: the shorter arc from a.
Quat4 near_to(const Quat4& a, Quat4 b) {
    if (dot4(a, b) < 0)
        for (double& c : b) c = -c;
    return b;
}

}  // namespace

Quaternion normalize(Quaternion q) { return narrow(unit(widen(q))); }

// Shepperd, "Quaternion from rotation matrix", J. Guidance and Control 1(3), 1978. With
// q = (x, y, z, w): trace = 4w^2 - 1, m00 = 1 - 2(y^2 + z^2), and the off-diagonal sums and
// differences give 4xy, 4wz and so on. Pick the largest of w^2, x^2, y^2, z^2 to divide by.
Quaternion quaternion_from_rotation(const Matrix4& rotation) {
    const auto& m = rotation.m;
    const double m00 = m[0][0], m11 = m[1][1], m22 = m[2][2];
    const double trace = m00 + m11 + m22;
    Quat4 q;
    if (trace >= m00 && trace >= m11 && trace >= m22) {
        const double w = 0.5 * std::sqrt(std::max(0.0, 1 + trace));
        const double s = 0.25 / w;
        q = {(double(m[2][1]) - m[1][2]) * s, (double(m[0][2]) - m[2][0]) * s,
             (double(m[1][0]) - m[0][1]) * s, w};
    } else if (m00 >= m11 && m00 >= m22) {
        const double x = 0.5 * std::sqrt(std::max(0.0, 1 + m00 - m11 - m22));
        const double s = 0.25 / x;
        q = {x, (double(m[0][1]) + m[1][0]) * s, (double(m[0][2]) + m[2][0]) * s,
             (double(m[2][1]) - m[1][2]) * s};
    } else if (m11 >= m22) {
        const double y = 0.5 * std::sqrt(std::max(0.0, 1 - m00 + m11 - m22));
        const double s = 0.25 / y;
        q = {(double(m[0][1]) + m[1][0]) * s, y, (double(m[1][2]) + m[2][1]) * s,
             (double(m[0][2]) - m[2][0]) * s};
    } else {
        const double z = 0.5 * std::sqrt(std::max(0.0, 1 - m00 - m11 + m22));
        const double s = 0.25 / z;
        q = {(double(m[0][2]) + m[2][0]) * s, (double(m[1][2]) + m[2][1]) * s, z,
             (double(m[1][0]) - m[0][1]) * s};
    }
    return narrow(unit(q));
}

// The standard product form (Shoemake 1985) with s = 2 / |q|^2, so that a quaternion slightly
// off unit length still gives an orthonormal matrix to rounding.
Matrix4 rotation_matrix(Quaternion q) {
    const Quat4 d = widen(q);
    const double x = d[0], y = d[1], z = d[2], w = d[3];
    const double s = 2 / dot4(d, d);
    Matrix4 r = Matrix4::identity();
    r.m[0][0] = float(1 - s * (y * y + z * z));
    r.m[0][1] = float(s * (x * y - w * z));
    r.m[0][2] = float(s * (x * z + w * y));
    r.m[1][0] = float(s * (x * y + w * z));
    r.m[1][1] = float(1 - s * (x * x + z * z));
    r.m[1][2] = float(s * (y * z - w * x));
    r.m[2][0] = float(s * (x * z - w * y));
    r.m[2][1] = float(s * (y * z + w * x));
    r.m[2][2] = float(1 - s * (x * x + y * y));
    return r;
}

float rotation_angle_between(Quaternion a, Quaternion b) {
    const Quat4 qa = unit(widen(a));
    const Quat4 qb = near_to(qa, unit(widen(b)));
    // The arc between them on the 3-sphere is half the rotation angle.
    return float(4 * half_arc(qa, qb));
}

Quaternion slerp(Quaternion a, Quaternion b, float t) {
    const Quat4 qa = unit(widen(a));
    const Quat4 qb = near_to(qa, unit(widen(b)));
    const double alpha = 2 * half_arc(qa, qb);  // the arc from a to b on the 3-sphere
    double wa = 1 - double(t), wb = t;
    // Below this arc the sine ratios differ from the linear weights by a factor within
    // alpha^2 / 6 < 2e-7 of 1, which moves the normalised result by under alpha times that, far
    // below float rounding: the normalised linear interpolation is as good and has no 0/0.
    if (alpha > 1e-3) {
        const double inv_sin = 1 / std::sin(alpha);
        wa = std::sin(wa * alpha) * inv_sin;
        wb = std::sin(wb * alpha) * inv_sin;
    }
    Quat4 r;
    for (int i = 0; i < 4; ++i) r[i] = wa * qa[i] + wb * qb[i];
    return narrow(unit(r));
}

}  // namespace glint
