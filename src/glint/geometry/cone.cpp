// The frustum's side as a quadratic along the ray, solved in double near the axis' midpoint; the
// caps as planes across the axis; normals and uv.
#include "glint/geometry/cone.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>

#include "glint/geometry/axis_frame.h"
#include "glint/geometry/disk.h"
#include "glint/geometry/near_ray.h"
#include "glint/math/constants.h"
#include "glint/math/quadratic.h"

namespace glint {

namespace {

enum Part : std::uint32_t { kSide = 0, kBaseCap = 1, kApexCap = 2 };

// Sides and caps overlap by this relative amount at the rims, so that rounding opens no cracks
// between them (a ray through the rim is accepted by one or the other).
constexpr float kSeamTolerance = 1e-6f;

// What surface_at derives from the description, in the frame of the axis, in double.
struct Frustum {
    Vector3d mid;  // the axis' midpoint
    Vector3d axis;
    double half_length;
    double base_radius, apex_radius;
    double slope;  // k = d rho / d y

    Point3 mid_point() const { return to_point(mid.to_float()); }
};

Frustum frustum_of(const Cone& cone) {
    const Vector3d base(cone.base), apex(cone.apex);
    const Vector3d along = apex - base;
    const double axis_length = std::sqrt(dot(along, along));
    return {(base + apex) * 0.5, along * (1 / axis_length),
            0.5 * axis_length,   cone.base_radius,
            cone.apex_radius,    (double{cone.apex_radius} - cone.base_radius) / axis_length};
}

// Whether the ray's line passes the axis' line farther than the wider radius: then it misses the
// side and the caps, and the solve in double below can be skipped. Most rays that reach a thin
// cylinder's box pass it by. In float, with a slack far above this test's rounding: the reach
// (widest + 1e-4 (widest + s)), s = |w| |axis| / |n| (a few ulps of |origin - base| / sin(angle
// to the axis), and of the radius), is bounded without a square root or a division by
// (a + b)^2 <= 1.01 a^2 + 101 b^2: it never rejects a hit. Rays nearly along the axis are not
// judged.
bool passes_clear(const Cone& cone, const Ray& ray) {
    const Vector3 axis = cone.apex - cone.base;
    const Vector3 w = ray.origin - cone.base;
    const Vector3 n = cross(ray.direction, axis);
    const float nn = dot(n, n), aa = dot(axis, axis);
    if (!(nn > 1e-6f * aa)) return false;  // nearly parallel (or NaN): left to the full test
    const float widest = std::max(cone.base_radius, cone.apex_radius) * (1 + 1e-4f);
    const float wn = dot(w, n);
    // wn^2 > reach^2 nn, with reach^2 <= 1.01 widest^2 + 101 (1e-4 s)^2.
    return wn * wn > 1.01f * widest * widest * nn + 1.01e-6f * dot(w, w) * aa;
}

}  // namespace

Bounds3 Cone::bounds() const {
    const Vector3 axis = apex - base;
    return merge(disk_bounds(base, axis, base_radius), disk_bounds(apex, axis, apex_radius));
}

std::optional<ShapeHit> Cone::intersect(const Ray& ray, Interval t_range) const {
    if (passes_clear(*this, ray)) return std::nullopt;
    // In double: the side's quadratic cancels for rays nearly parallel to the side or the axis.
    // Heights along the axis are taken against the unnormalised axis A = apex - base and scaled
    // back by 1 / |A|^2 where they pair up: no square root, one division.
    const Vector3d base_d(base), apex_d(apex);
    const Vector3d along = apex_d - base_d;
    const double aa = dot(along, along);  // |A|^2 = (2 h)^2
    const double inv_aa = 1 / aa;
    const NearRay near = near_ray(ray, (base_d + apex_d) * 0.5);
    const Vector3d q = near.origin, d = near.direction;
    // The ray's closest approach to the midpoint is outside the bounding sphere: no hit.
    const double widest = std::max<double>(base_radius, apex_radius);
    const double bounding2 = 0.25 * aa + widest * widest;
    const double qq = dot(q, q);
    if (qq > bounding2 * (1 + 1e-6)) return std::nullopt;

    // Across the axis: q_perp = q - y0 a and d_perp = d - yd a (a the unit axis, y0 = Y0 / |A|,
    // yd = Yd / |A|), whose products follow from the full ones without forming them.
    const double y0 = dot(q, along), yd = dot(d, along);  // Y0 and Yd: |A| times the heights
    const double dd_perp = dot(d, d) - yd * yd * inv_aa;
    const double qd_perp = dot(q, d) - y0 * yd * inv_aa;
    const double qq_perp = qq - y0 * y0 * inv_aa;
    const double mid_radius = 0.5 * (double{base_radius} + apex_radius);
    // The slope k = (apex_radius - base_radius) / |A| times a height, in the scaled heights.
    const double widening = (double{apex_radius} - base_radius) * inv_aa;
    const double rho0 = mid_radius + widening * y0;  // the cone's radius at the origin's height
    const double k_yd = widening * yd;
    // |q_perp + s d_perp|^2 = (rho0 + k yd s)^2, collected by powers of s.
    const double alpha = dd_perp - k_yd * k_yd;
    const double beta = 2 * (qd_perp - k_yd * rho0);
    const double gamma = qq_perp - rho0 * rho0;

    std::optional<ShapeHit> best;
    const auto consider = [&](double s, std::uint32_t part) {
        const auto t = static_cast<float>(near.t_shift + s);
        if (t_range.contains(t) && (!best || t < best->t)) best = ShapeHit{t, 0, 0, part};
    };
    // |height| <= h, scaled: |Y0 + s Yd| <= h |A| = |A|^2 / 2.
    const double half_aa = 0.5 * aa;
    const double h = half_aa * (1 + kSeamTolerance);
    if (const auto roots = solve_quadratic_double(alpha, beta, gamma)) {
        // Parallel to the side (alpha = 0) gives the one root twice; the height test removes
        // the far roots of nearly parallel rays and the mirrored nappe.
        // The far root is looked at only when the near one is not taken.
        for (const double s : {roots->t0, roots->t1}) {
            if (std::abs(y0 + s * yd) <= h) consider(s, kSide);
            if (best) break;
        }
    }
    if (capped && yd != 0) {
        const auto cap = [&](double y_cap, double radius, std::uint32_t part) {
            if (radius == 0) return;
            const double s = (y_cap - y0) / yd;
            const double r2 = qq_perp + s * (2 * qd_perp + s * dd_perp);  // |q_perp + s d_perp|^2
            if (r2 <= radius * radius * (1 + 2 * kSeamTolerance)) consider(s, part);
        };
        cap(-half_aa, base_radius, kBaseCap);
        cap(half_aa, apex_radius, kApexCap);
    }
    return best;
}

SurfacePoint Cone::surface_at(const Ray& ray, const ShapeHit& hit) const {
    const Frustum f = frustum_of(*this);
    const Vector3 axis = f.axis.to_float();
    const auto half_length = static_cast<float>(f.half_length);
    const Vector3 offset = ray.at(hit.t) - f.mid_point();
    const float y = dot(offset, axis);
    const Vector3 across = offset - axis * y;
    const float rho = length(across);
    const AxisFrame frame = axis_frame(axis);
    const Vector3 radial = rho > 0 ? across / rho : frame.x;
    const float u = angle_around(frame, radial);
    // The way the radial direction turns as u grows (angle_around's sense).
    const Vector3 tangent = frame.x * dot(radial, frame.z) - frame.z * dot(radial, frame.x);

    SurfacePoint sp;
    if (hit.part == kSide) {
        // The nearest point of the side's generating segment, (base_radius, -h) to
        // (apex_radius, h) in the (rho, y) half-plane: the point projected onto the surface.
        const float dr = apex_radius - base_radius, dy = 2 * half_length;
        const float w = std::clamp(
            ((rho - base_radius) * dr + (y + half_length) * dy) / (dr * dr + dy * dy), 0.0f, 1.0f);
        sp.p = f.mid_point() + axis * (-half_length + w * dy) + radial * (base_radius + w * dr);
        const Vector3 unnormalised = radial - axis * static_cast<float>(f.slope);
        sp.normal = Normal3(normalize(unnormalised));
        sp.uv = {u, w};
        // u turns the radial direction (and the normal with it) about the axis; v slides
        // along the generating segment.
        sp.dpdu = tangent * (2 * kPi * (base_radius + w * dr));
        sp.dpdv = axis * dy + radial * dr;
        sp.dndu = tangent * (2 * kPi / length(unnormalised));
    } else {
        const bool at_base = hit.part == kBaseCap;
        const float cap_radius = at_base ? base_radius : apex_radius;
        const float rho_on_cap = std::min(rho, cap_radius);
        sp.p = f.mid_point() + axis * (at_base ? -half_length : half_length) + radial * rho_on_cap;
        sp.normal = Normal3(at_base ? -axis : axis);
        sp.uv = {u, rho_on_cap / cap_radius};
        sp.dpdu = tangent * (2 * kPi * rho_on_cap);
        sp.dpdv = radial * cap_radius;
    }
    sp.has_derivatives = true;
    sp.shading_normal = sp.normal;
    return sp;
}

std::string describe_problem(const Cone& cone) {
    std::ostringstream out;
    const float axis_length = length(cone.apex - cone.base);
    if (!is_finite(cone.base) || !is_finite(cone.apex)) {
        out << "cone base and apex must be finite";
    } else if (!(cone.base_radius >= 0) || !std::isfinite(cone.base_radius)) {
        out << "cone base_radius must be >= 0, got " << cone.base_radius;
    } else if (!(cone.apex_radius >= 0) || !std::isfinite(cone.apex_radius)) {
        out << "cone apex_radius must be >= 0, got " << cone.apex_radius;
    } else if (cone.base_radius == 0 && cone.apex_radius == 0) {
        out << "cone base_radius and apex_radius must not both be 0";
    } else if (!(axis_length > 0)) {
        out << "cone apex must differ from its base";
    } else if (!std::isfinite(axis_length)) {
        out << "cone is too long: the distance from base to apex overflows a float";
    }
    return out.str();
}

}  // namespace glint
