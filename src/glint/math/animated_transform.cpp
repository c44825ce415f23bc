// Keyframe decomposition and interpolation (Shoemake and Duff 1992), and conservative boxes
// around a moving object from samples padded by the interpolation error of a curve.
#include "glint/math/animated_transform.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace glint {
namespace {

// 3x3 matrices in double for the decomposition and the interpolated products.
using Mat3 = std::array<std::array<double, 3>, 3>;

Mat3 upper3(const Matrix4& a) {
    Mat3 r;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) r[i][j] = a.m[i][j];
    return r;
}

// The affine matrix with upper 3x3 a and translation t.
Matrix4 affine_matrix(const Mat3& a, const std::array<double, 3>& t) {
    Matrix4 r = Matrix4::identity();
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) r.m[i][j] = float(a[i][j]);
        r.m[i][3] = float(t[i]);
    }
    return r;
}

Mat3 operator*(const Mat3& a, const Mat3& b) {
    Mat3 r{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k) r[i][j] += a[i][k] * b[k][j];
    return r;
}

Mat3 transpose(const Mat3& a) {
    Mat3 r;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) r[i][j] = a[j][i];
    return r;
}

// wa * a + wb * b.
Mat3 combine(double wa, const Mat3& a, double wb, const Mat3& b) {
    Mat3 r;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) r[i][j] = wa * a[i][j] + wb * b[i][j];
    return r;
}

double determinant(const Mat3& a) {
    return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
           a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
           a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
}

// The adjugate over the determinant; the caller knows a is not singular.
Mat3 inverse(const Mat3& a) {
    Mat3 r;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            // Cofactor of a[j][i], with the cyclic index trick supplying the sign.
            const int j1 = (j + 1) % 3, j2 = (j + 2) % 3, i1 = (i + 1) % 3, i2 = (i + 2) % 3;
            r[i][j] = a[j1][i1] * a[j2][i2] - a[j1][i2] * a[j2][i1];
        }
    const double inv_det = 1 / determinant(a);
    for (auto& row : r)
        for (double& x : row) x *= inv_det;
    return r;
}

double frobenius_norm(const Mat3& a) {
    double sum = 0;
    for (const auto& row : a)
        for (double x : row) sum += x * x;
    return std::sqrt(sum);
}

// An upper bound on the operator (spectral) norm: the smaller of the Frobenius norm and
// sqrt(|a|_1 |a|_inf) (Golub and Van Loan, 2.3.3), the latter exact for diagonal matrices.
double operator_norm_bound(const Mat3& a) {
    double max_row = 0, max_column = 0;
    for (int i = 0; i < 3; ++i) {
        double row = 0, column = 0;
        for (int j = 0; j < 3; ++j) {
            row += std::abs(a[i][j]);
            column += std::abs(a[j][i]);
        }
        max_row = std::max(max_row, row);
        max_column = std::max(max_column, column);
    }
    return std::min(frobenius_norm(a), std::sqrt(max_row * max_column));
}

// Rounding up so that a bound computed with rounding stays a bound.
float round_up(double bound) { return float(bound * (1 + 1e-6)); }

std::string number(float value) {
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

bool is_affine(const Matrix4& a) {
    for (const auto& row : a.m)
        for (float x : row)
            if (!std::isfinite(x)) return false;
    return a.m[3][0] == 0 && a.m[3][1] == 0 && a.m[3][2] == 0 && a.m[3][3] == 1;
}

bool mirrors(const Matrix4& a) { return determinant(upper3(a)) < 0; }

// The parts of two keyframes blended at fraction u: translation and stretch linearly, rotation
// by slerp.
struct Blend {
    std::array<double, 3> translation;
    Mat3 rotation;
    Mat3 stretch;
};

Blend blend_parts(const Decomposed& a, const Decomposed& b, float u) {
    const double wa = 1 - double(u), wb = u;
    return {
        {wa * a.translation.x + wb * b.translation.x, wa * a.translation.y + wb * b.translation.y,
         wa * a.translation.z + wb * b.translation.z},
        upper3(rotation_matrix(slerp(a.rotation, b.rotation, u))),
        combine(wa, upper3(a.stretch), wb, upper3(b.stretch))};
}

// The box of an affine map of box b, in double: the image of the centre, plus the absolute
// matrix times the half-diagonal (Arvo 1990, "Transforming axis-aligned bounding boxes").
Bounds3 map_box(const Mat3& m, const std::array<double, 3>& t, const Bounds3& b) {
    std::array<float, 3> lo, hi;
    for (int i = 0; i < 3; ++i) {
        double centre = t[i], half = 0;
        for (int j = 0; j < 3; ++j) {
            centre += m[i][j] * ((double(b.min[j]) + b.max[j]) / 2);
            half += std::abs(m[i][j]) * ((double(b.max[j]) - b.min[j]) / 2);
        }
        lo[i] = float(centre - half);
        hi[i] = float(centre + half);
    }
    return {{lo[0], lo[1], lo[2]}, {hi[0], hi[1], hi[2]}};
}

Bounds3 whole_space() {
    return {{-kInfinity, -kInfinity, -kInfinity}, {kInfinity, kInfinity, kInfinity}};
}

// A box grown by `pad` on every side.
Bounds3 padded(const Bounds3& b, float pad) {
    const Vector3 d{pad, pad, pad};
    return {b.min - d, b.max + d};
}

}  // namespace

std::optional<Decomposed> decompose(const Matrix4& affine) {
    if (!is_affine(affine) || !inverse(affine)) return std::nullopt;
    const Mat3 a = upper3(affine);
    const double det = determinant(a);
    if (!(det != 0)) return std::nullopt;

    // Newton's iteration for the orthogonal polar factor, scaled by g = sqrt(|Q^-1| / |Q|)
    // (Higham 1986) so that strongly scaled matrices converge in a handful of steps rather than
    // halving their way to 1. It converges quadratically; stop once a step is at rounding level.
    Mat3 q = a;
    for (int iteration = 0; iteration < 100; ++iteration) {
        const Mat3 q_inv = inverse(q);
        const double g = std::sqrt(frobenius_norm(q_inv) / frobenius_norm(q));
        const Mat3 next = combine(g / 2, q, 1 / (2 * g), transpose(q_inv));
        const double step = frobenius_norm(combine(1, next, -1, q));
        q = next;
        if (step <= 1e-12) break;
    }
    // Q is a rotation times the sign of det A. When it mirrors, R = -Q and S = -(Q^T A): the
    // negation commutes with everything, so keyframes that all mirror turn and stretch between
    // each other just as unmirrored ones do, their stretches all negative definite.
    if (det < 0) q = combine(-1, q, 0, q);
    Mat3 s = transpose(q) * a;
    s = combine(0.5, s, 0.5, transpose(s));  // symmetric in exact arithmetic; make it so

    Decomposed parts;
    parts.translation = {affine.m[0][3], affine.m[1][3], affine.m[2][3]};
    parts.rotation = quaternion_from_rotation(affine_matrix(q, {0, 0, 0}));
    parts.stretch = affine_matrix(s, {0, 0, 0});
    return parts;
}

Matrix4 recompose(const Decomposed& parts) {
    const Mat3 m = upper3(rotation_matrix(parts.rotation)) * upper3(parts.stretch);
    const Vector3 t = parts.translation;
    return affine_matrix(m, {t.x, t.y, t.z});
}

AnimatedTransform::AnimatedTransform() : AnimatedTransform(Transform()) {}

AnimatedTransform::AnimatedTransform(const Transform& world_from_object)
    : keyframes_{{0, world_from_object}} {}

AnimatedTransform::AnimatedTransform(std::vector<Keyframe> keyframes)
    : keyframes_(std::move(keyframes)) {
    if (const std::string problem = describe_problem(keyframes_); !problem.empty())
        throw std::invalid_argument(problem);
    for (const Keyframe& k : keyframes_)
        if (!(k.world_from_object == keyframes_.front().world_from_object)) static_ = false;
    if (keyframes_.size() == 1) return;

    for (const Keyframe& k : keyframes_) parts_.push_back(*decompose(k.world_from_object.matrix()));
    for (std::size_t i = 0; i + 1 < keyframes_.size(); ++i) {
        const Decomposed& a = parts_[i];
        const Decomposed& b = parts_[i + 1];
        const Mat3 sa = upper3(a.stretch), sb = upper3(b.stretch);
        Segment s;
        s.is_static = keyframes_[i].world_from_object == keyframes_[i + 1].world_from_object;
        s.rotation_angle = round_up(rotation_angle_between(a.rotation, b.rotation));
        // The norm is convex, so its bound at the ends bounds it on the segment between.
        s.stretch_norm = round_up(std::max(operator_norm_bound(sa), operator_norm_bound(sb)));
        s.stretch_change = round_up(operator_norm_bound(combine(1, sb, -1, sa)));
        s.translation = round_up(std::max(length(a.translation), length(b.translation)));
        segments_.push_back(s);
    }
}

std::string AnimatedTransform::describe_problem(const std::vector<Keyframe>& keyframes) {
    if (keyframes.empty()) return "a moving transform needs at least one keyframe";
    const std::string of = " of " + std::to_string(keyframes.size());
    auto name = [&](std::size_t i) {
        return "keyframe " + std::to_string(i + 1) + of + " (time " + number(keyframes[i].time) +
               ")";
    };
    for (std::size_t i = 0; i < keyframes.size(); ++i) {
        if (!std::isfinite(keyframes[i].time))
            return "keyframe " + std::to_string(i + 1) + of + " has time " +
                   number(keyframes[i].time) + ": times must be finite";
        if (i > 0 && !(keyframes[i].time > keyframes[i - 1].time))
            return name(i) + " is not later than " + name(i - 1) +
                   ": keyframe times must increase strictly";
    }
    if (keyframes.size() == 1) return "";
    for (std::size_t i = 0; i < keyframes.size(); ++i) {
        const Matrix4& m = keyframes[i].world_from_object.matrix();
        if (!is_affine(m))
            return name(i) +
                   " has a projective or non-finite matrix: only affine transforms "
                   "(bottom row 0 0 0 1) can be interpolated";
        if (!decompose(m)) return name(i) + " has a singular matrix: it flattens space";
    }
    for (std::size_t i = 0; i + 1 < keyframes.size(); ++i) {
        if (mirrors(keyframes[i].world_from_object.matrix()) !=
            mirrors(keyframes[i + 1].world_from_object.matrix()))
            return name(i) + " and " + name(i + 1) +
                   " differ in handedness (one mirrors, the other does not): the motion between "
                   "them would flatten the object through a singular transform";
    }
    return "";
}

float AnimatedTransform::segment_fraction(std::size_t i, float time) const {
    const float t0 = keyframes_[i].time, t1 = keyframes_[i + 1].time;
    return std::clamp((time - t0) / (t1 - t0), 0.0f, 1.0f);
}

Transform AnimatedTransform::at(float time) const {
    const std::vector<Keyframe>& k = keyframes_;
    if (static_ || !(time > k.front().time)) return k.front().world_from_object;
    if (time >= k.back().time) return k.back().world_from_object;
    // The last keyframe at or before `time`; the one after it exists as time < the last time.
    const auto after =
        std::upper_bound(k.begin(), k.end(), time,
                         [](float t, const Keyframe& keyframe) { return t < keyframe.time; });
    const std::size_t i = std::size_t(after - k.begin()) - 1;
    if (k[i].time == time || segments_[i].is_static) return k[i].world_from_object;
    return interpolate(i, segment_fraction(i, time));
}

Transform AnimatedTransform::interpolate(std::size_t i, float u) const {
    const Blend blend = blend_parts(parts_[i], parts_[i + 1], u);
    // The inverse composed from the parts' inverses, S^-1 R^T translate(-t): the rotation's is
    // its transpose, and S (a blend of two definite matrices of one sign) is definite.
    const Mat3 inv = inverse(blend.stretch) * transpose(blend.rotation);
    std::array<double, 3> inv_t{};
    for (int row = 0; row < 3; ++row)
        for (int j = 0; j < 3; ++j) inv_t[row] -= inv[row][j] * blend.translation[j];
    return {affine_matrix(blend.rotation * blend.stretch, blend.translation),
            affine_matrix(inv, inv_t)};
}

// The box holds the curve p(u) = T(u) + R(u) S(u) x of every object point x over [u0, u1].
// Between samples u_j and u_j + h, a curve differs from the chord between its sample points by
// at most h^2 / 8 max|p''| in each coordinate (the error of linear interpolation), and the chord
// lies in the union of the two sample boxes. With T and S linear in u and R(u) = R_a times a
// turn about a fixed axis at angular speed phi (slerp's constant speed),
//   p'' = R'' S x + 2 R' S' x,  |p''| <= (phi^2 |S| + 2 phi |S_b - S_a|) |x|,
// and |x| is at most the object box's farthest corner from the origin. Translation drops out,
// so a pure translation or scale is bounded exactly by its end boxes. Enough samples are taken
// to make that pad a thousandth of the swept radius |S| |x|. A further pad of 1e-5 times
// |T| + |S| |x| covers float rounding: at() computes points to within 3e-7 of that in tests,
// and the sample boxes here are computed in double.
Bounds3 AnimatedTransform::segment_bounds(std::size_t i, const Bounds3& object_bounds, float u0,
                                          float u1) const {
    constexpr double kTolerance = 1e-3;
    constexpr int kMaxSamples = 256;
    constexpr double kRounding = 1e-5;
    const Segment& segment = segments_[i];

    double radius = 0;
    for (int corner = 0; corner < 8; ++corner) {
        const Point3 p{corner & 1 ? object_bounds.max.x : object_bounds.min.x,
                       corner & 2 ? object_bounds.max.y : object_bounds.min.y,
                       corner & 4 ? object_bounds.max.z : object_bounds.min.z};
        radius = std::max(radius, double(length(to_vector(p))));
    }
    radius = round_up(radius);
    const double phi = segment.rotation_angle;
    const double swept_radius = segment.stretch_norm * radius;
    const double curvature = (phi * phi * segment.stretch_norm + 2 * phi * segment.stretch_change) *
                             radius;  // >= max |p''|
    const double span = double(u1) - u0;
    int samples = 1;
    if (curvature > 0 && swept_radius > 0 && span > 0) {
        const double wanted = span * std::sqrt(curvature / (8 * kTolerance * swept_radius));
        samples = int(std::clamp(std::ceil(wanted), 1.0, double(kMaxSamples)));
    }
    Bounds3 box;
    for (int j = 0; j <= samples; ++j) {
        const float u = j == samples ? u1 : float(u0 + span * j / samples);
        const Blend blend = blend_parts(parts_[i], parts_[i + 1], u);
        box = merge(box, map_box(blend.rotation * blend.stretch, blend.translation, object_bounds));
    }
    const double h = span / samples;
    const double pad =
        h * h / 8 * curvature + kRounding * (double(segment.translation) + swept_radius);
    return padded(box, round_up(pad));
}

Bounds3 AnimatedTransform::motion_bounds(const Bounds3& object_bounds, float t0, float t1) const {
    if (object_bounds.is_empty()) return Bounds3{};
    if (!object_bounds.is_finite()) return whole_space();
    const std::vector<Keyframe>& k = keyframes_;
    if (static_) return k.front().world_from_object(object_bounds);
    if (std::isnan(t0) || std::isnan(t1)) t0 = start_time(), t1 = end_time();
    if (t1 < t0) std::swap(t0, t1);

    // at() returns a keyframe's own transform at its time and, clamped, outside the keyframes.
    // Its box of transformed corners holds the transformed box even in float: each coordinate
    // of the rounded product is monotonic in each coordinate of the point.
    Bounds3 r;
    if (t0 < k.front().time) r = merge(r, k.front().world_from_object(object_bounds));
    if (t1 > k.back().time) r = merge(r, k.back().world_from_object(object_bounds));
    for (const Keyframe& keyframe : k)
        if (t0 <= keyframe.time && keyframe.time <= t1)
            r = merge(r, keyframe.world_from_object(object_bounds));
    // Between keyframes, the part of each segment that [t0, t1] covers.
    for (std::size_t i = 0; i + 1 < k.size(); ++i) {
        const float from = std::max(t0, k[i].time), to = std::min(t1, k[i + 1].time);
        if (!(from < to)) continue;
        if (segments_[i].is_static) {
            r = merge(r, k[i].world_from_object(object_bounds));
        } else {
            r = merge(r, segment_bounds(i, object_bounds, segment_fraction(i, from),
                                        segment_fraction(i, to)));
        }
    }
    return r;
}

}  // namespace glint
