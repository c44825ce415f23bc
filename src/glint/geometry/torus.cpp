// The torus as a quartic in double near its centre, with each root polished on the torus
// function itself; the normal and the two angles as uv.
#include "glint/geometry/torus.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "glint/geometry/axis_frame.h"
#include "glint/geometry/disk.h"
#include "glint/geometry/near_ray.h"
#include "glint/math/constants.h"
#include "glint/math/quartic.h"

namespace glint {

namespace {

// The ray near the torus in double: P(s) = q + s d relative to the centre, a the unit axis.
struct TorusRay {
    Vector3d q, d, a;
    double major2, minor2;

    // F(P) = (|P|^2 + R^2 - r^2)^2 - 4 R^2 (|P|^2 - (P.a)^2), and dF/ds = grad F . d with
    // grad F = 4 (|P|^2 + R^2 - r^2) P - 8 R^2 (P - (P.a) a).
    double value(double s, double& derivative) const {
        const Vector3d p = q + d * s;
        const double p2 = dot(p, p), p_a = dot(p, a), p_d = dot(p, d);
        const double g = p2 + major2 - minor2;
        derivative = 4 * g * p_d - 8 * major2 * (p_d - p_a * dot(d, a));
        return g * g - 4 * major2 * (p2 - p_a * p_a);
    }
};

// One Newton step on the torus function itself, kept only when it reduces |F|: the quartic's
// coefficients carry the cancellation of their expansion, which evaluating F directly avoids. A
// double root (F' = 0, a tangent ray) keeps its value.
double polish(const TorusRay& torus, double s) {
    double derivative = 0;
    const double f = torus.value(s, derivative);
    const double next = s - f / derivative;
    if (!std::isfinite(next)) return s;
    double unused = 0;
    return std::abs(torus.value(next, unused)) < std::abs(f) ? next : s;
}

}  // namespace

Bounds3 Torus::bounds() const {
    // disk_bounds gives the tube's centre circle; the tube adds its radius on every side.
    const Bounds3 circle = disk_bounds(center, to_vector(axis), major_radius);
    const float grow = minor_radius * (1 + 1e-6f);
    const Vector3 tube{grow, grow, grow};
    return {circle.min - tube, circle.max + tube};
}

std::optional<ShapeHit> Torus::intersect(const Ray& ray, Interval t_range) const {
    const NearRay near = near_ray(ray, Vector3d(center));
    const Vector3d axis_d(to_vector(axis));
    const TorusRay torus{near.origin, near.direction, axis_d * (1 / std::sqrt(dot(axis_d, axis_d))),
                         double{major_radius} * major_radius, double{minor_radius} * minor_radius};
    const double dd = dot(torus.d, torus.d), m = dot(torus.q, torus.q);
    // The origin is the ray's point nearest the centre: outside the bounding sphere there is no
    // hit, and inside, every hit is within half a chord of it.
    const double extent = double{major_radius} + minor_radius;
    const double extent2 = extent * extent * (1 + 1e-6);
    if (m > extent2) return std::nullopt;
    const double half_chord = std::sqrt((extent2 - m) / dd);
    if (near.t_shift + half_chord < t_range.min || near.t_shift - half_chord > t_range.max) {
        return std::nullopt;
    }

    // The torus equation along the ray, expanded by powers of s (|d|^2 = dd kept general):
    // with n = q.d, k = |q|^2 + R^2 - r^2, y0 = q.a, yd = d.a,
    // (dd s^2 + 2 n s + k)^2 - 4 R^2 ((dd - yd^2) s^2 + 2 (n - y0 yd) s + |q|^2 - y0^2) = 0.
    const double n = dot(torus.q, torus.d);
    const double y0 = dot(torus.q, torus.a), yd = dot(torus.d, torus.a);
    const double k = m + torus.major2 - torus.minor2;
    const double four_major2 = 4 * torus.major2;
    const QuarticRoots roots = solve_quartic(
        dd * dd, 4 * dd * n, 4 * n * n + 2 * dd * k - four_major2 * (dd - yd * yd),
        4 * n * k - 2 * four_major2 * (n - y0 * yd), k * k - four_major2 * (m - y0 * y0));
    for (double s : roots) {
        const auto t = static_cast<float>(near.t_shift + polish(torus, s));
        if (t_range.contains(t)) return ShapeHit{t};
    }
    return std::nullopt;
}

SurfacePoint Torus::surface_at(const Ray& ray, const ShapeHit& hit) const {
    const Vector3 a = normalize(to_vector(axis));
    const Vector3 offset = ray.at(hit.t) - center;
    const float y = dot(offset, a);
    const Vector3 across = offset - a * y;
    const float rho = length(across);
    const AxisFrame frame = axis_frame(a);
    // Only points on the axis lack a direction away from it; no ring torus reaches there.
    const Vector3 radial = rho > 0 ? across / rho : frame.x;
    const Vector3 from_tube_centre = offset - radial * major_radius;
    const float distance_from_tube_centre = length(from_tube_centre);
    const Vector3 n =
        distance_from_tube_centre > 0 ? from_tube_centre / distance_from_tube_centre : radial;
    SurfacePoint sp;
    sp.p = center + radial * major_radius + n * minor_radius;  // projected onto the tube
    sp.normal = sp.shading_normal = Normal3(n);
    const float theta = std::atan2(dot(n, a), dot(n, radial));
    const float v = (theta < 0 ? theta + 2 * kPi : theta) / (2 * kPi);
    sp.uv = {angle_around(frame, radial), v < 1 ? v : 0};
    return sp;
}

std::string describe_problem(const Torus& torus) {
    std::ostringstream out;
    const Vector3 axis = to_vector(torus.axis);
    if (!is_finite(torus.center)) {
        out << "torus center must be finite";
    } else if (!is_finite(axis) || length_squared(axis) == 0) {
        out << "torus axis must be a finite, non-zero direction";
    } else if (!(torus.minor_radius > 0) || !std::isfinite(torus.minor_radius)) {
        out << "torus minor_radius must be > 0, got " << torus.minor_radius;
    } else if (!(torus.major_radius > torus.minor_radius) || !std::isfinite(torus.major_radius)) {
        out << "torus major_radius must be greater than minor_radius (a ring torus), got "
               "major_radius "
            << torus.major_radius << " and minor_radius " << torus.minor_radius;
    }
    return out.str();
}

}  // namespace glint
