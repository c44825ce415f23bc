// The warps of warp.h. Each derivation is given where it is not the textbook one.
#include "glint/sampling/warp.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

namespace glint {
namespace {

// The largest float below 1: where a re-stretched u must stay to remain in [0, 1).
constexpr float kOneMinusEpsilon = 0x1.fffffep-1f;

// A unit vector from the cosine and sine of its angle to +z and its azimuth phi.
Vector3 spherical_direction(float cos_theta, float sin_theta, float phi) {
    return {sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta};
}

// c ? x : y without a branch: GCC compiles a float ?: to one, which a coin toss mispredicts half
// the time.
float select(bool c, float x, float y) {
    const std::uint32_t mask = 0u - std::uint32_t(c);
    return std::bit_cast<float>((std::bit_cast<std::uint32_t>(x) & mask) |
                                (std::bit_cast<std::uint32_t>(y) & ~mask));
}

// The sine and cosine of x in [-pi/4, pi/4], by the minimax polynomials of Moshier's Cephes
// library (sinf.c, cosf.c), within about an ulp there: the library's sincosf spends most of its
// time reducing an argument that is already in range.
struct SineCosine {
    float sin, cos;
};
SineCosine sin_cos_quarter_turn(float x) {
    const float z = x * x;
    const float sin =
        ((-1.9515295891e-4f * z + 8.3321608736e-3f) * z - 1.6666654611e-1f) * z * x + x;
    const float cos =
        ((2.443315711809948e-5f * z - 1.388731625493765e-3f) * z + 4.166664568298827e-2f) * z * z -
        0.5f * z + 1;
    return {sin, cos};
}

}  // namespace

Point2 sample_uniform_disk(Point2 u) {
    // The square [-1,1]^2 in wedges: in the wedge |a| > |b| the radius is |a| and the angle
    // runs linearly with b/a across pi/4 either side of the axis; likewise for |b| >= |a|, where
    // the angle is pi/2 - (pi/4) a/b, whose cosine and sine are the sine and cosine of
    // (pi/4) a/b. Without branches: for uniform u the wedge is a coin toss, which a branch
    // mispredicts half the time (the disk and sincosf were 8% of bench/distributed_vs_povray's
    // profile before).
    const float a = 2 * u.x - 1, b = 2 * u.y - 1;
    const bool across = std::abs(a) > std::abs(b);
    const float r = select(across, a, b), other = select(across, b, a);
    // At the centre r and other are both 0: the angle 0, the point the centre.
    const SineCosine sc = sin_cos_quarter_turn(kPi / 4 * (other / select(r != 0, r, 1)));
    return {r * select(across, sc.cos, sc.sin), r * select(across, sc.sin, sc.cos)};
}

float regular_polygon_area(int sides) {
    // `sides` triangles (centre, v_k, v_k+1) with two unit sides meeting at 2 pi / sides.
    return 0.5f * float(sides) * std::sin(2 * kPi / float(sides));
}

Point2 sample_regular_polygon(Point2 u, int sides, float rotation_radians) {
    // All wedges have the same area, so u.x picks one uniformly; what is left of u.x after the
    // pick is again uniform on [0, 1) and serves as the triangle's first number.
    const float scaled = u.x * float(sides);
    const int k = std::min(int(scaled), sides - 1);
    const float u_rest = std::min(scaled - float(k), kOneMinusEpsilon);
    const float step = 2 * kPi / float(sides);
    const float angle0 = rotation_radians + step * float(k), angle1 = angle0 + step;
    const Point2 b = sample_uniform_triangle({u_rest, u.y});
    const float b2 = 1 - b.x - b.y;
    // b.x weights the centre (the origin), b.y vertex k and b2 vertex k + 1.
    return {b.y * std::cos(angle0) + b2 * std::cos(angle1),
            b.y * std::sin(angle0) + b2 * std::sin(angle1)};
}

Point2 sample_uniform_triangle(Point2 u) {
    // Where u.x < u.y, (b0, b1) = (u.x/2, u.y - u.x/2) maps that half of the square linearly,
    // with Jacobian 1/2, onto {b0 < b1, b0 + b1 < 1}; the other half mirrors it onto
    // {b1 <= b0, b0 + b1 < 1}. Both linear with the same Jacobian: uniform.
    if (u.x < u.y) {
        const float b0 = u.x / 2;
        return {b0, u.y - b0};
    }
    const float b1 = u.y / 2;
    return {u.x - b1, b1};
}

Vector3 sample_uniform_sphere(Point2 u) {
    // z = 1 - 2 u.x; 1 - z^2 = 4 u.x (1 - u.x) keeps the radius accurate near the poles.
    const float z = 1 - 2 * u.x;
    const float r = 2 * std::sqrt(std::max(0.0f, u.x * (1 - u.x)));
    return {r * std::cos(2 * kPi * u.y), r * std::sin(2 * kPi * u.y), z};
}

Vector3 sample_uniform_cone(Point2 u, float cos_max) {
    // cos(theta) uniform on (cos_max, 1]: solid angle is linear in cos(theta). Working with
    // 1 - cos keeps the sine accurate for the tiny cones of small, distant lights.
    const float one_minus_cos = u.x * (1 - cos_max);
    const float sin_theta = std::sqrt(std::max(0.0f, one_minus_cos * (2 - one_minus_cos)));
    return spherical_direction(1 - one_minus_cos, sin_theta, 2 * kPi * u.y);
}

Vector3 sample_phong_lobe(Point2 u, float exponent) {
    // cos(alpha) = v^(1/(n+1)) with v uniform inverts the CDF of cos(alpha), whose density is
    // (n+1) cos^n on [0, 1]. v = 1 - u.x lies in (0, 1], never 0: a sample on the horizon
    // would have pdf 0 and turn an estimate f / pdf into 0 / 0. For large n cos(alpha) rounds
    // to 1 in float, so the sine comes from 1 - cos = -expm1(log(v)/(n+1)) instead.
    const float log_cos = std::log(1 - u.x) / (exponent + 1);
    const float one_minus_cos = -std::expm1(log_cos);
    const float sin_alpha = std::sqrt(std::max(0.0f, one_minus_cos * (2 - one_minus_cos)));
    return spherical_direction(std::exp(log_cos), sin_alpha, 2 * kPi * u.y);
}

float phong_lobe_pdf(float cos_alpha, float exponent) {
    if (cos_alpha < 0) return 0;
    return (exponent + 1) / (2 * kPi) * std::pow(cos_alpha, exponent);
}

Vector3 from_frame(Vector3 local, Vector3 axis) {
    Vector3 s, t;
    orthonormal_basis(axis, s, t);
    return s * local.x + t * local.y + axis * local.z;
}

namespace {

// The visible-wavelength density c / cosh^2(a (lambda - 538)) has the antiderivative
// (c / a) tanh(a (lambda - 538)). With T(lambda) = tanh(a (lambda - 538)), normalising over
// [360, 830] gives c = a / (T(830) - T(360)) and the CDF (T(lambda) - T(360)) / (T(830) -
// T(360)), which inverts to lambda = 538 + atanh(T(360) + u (T(830) - T(360))) / a.
constexpr float kWavelengthA = 0.0072f;
constexpr float kWavelengthCentre = 538;
constexpr float kWavelengthMin = 360, kWavelengthMax = 830;
constexpr float kTanhAtMin = -0.856910625469828f;         // tanh(0.0072 (360 - 538))
constexpr float kTanhRange = 1.8275019724100978f;         // tanh(0.0072 (830 - 538)) - kTanhAtMin
constexpr float kWavelengthNorm = 0.003939804229324407f;  // 0.0072 / kTanhRange

}  // namespace

float sample_visible_wavelength(float u) {
    const float t = kTanhAtMin + u * kTanhRange;
    const float lambda = kWavelengthCentre + std::atanh(t) / kWavelengthA;
    return std::clamp(lambda, kWavelengthMin, kWavelengthMax);
}

float visible_wavelength_pdf(float lambda_nm) {
    if (!(lambda_nm >= kWavelengthMin && lambda_nm <= kWavelengthMax)) return 0;
    const float c = std::cosh(kWavelengthA * (lambda_nm - kWavelengthCentre));
    return kWavelengthNorm / (c * c);
}

}  // namespace glint
