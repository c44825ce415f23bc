// The German lecture notes' geometric ray-sphere method, step by step with its early exits, and
// the sphere's normal and spherical uv.
#include "glint/geometry/sphere.h"

#include <algorithm>
#include <cmath>

#include "glint/math/constants.h"

namespace glint {

Bounds3 Sphere::bounds() const {
    const Vector3 r{radius, radius, radius};
    return {center - r, center + r};
}

// The steps are numbered as in the notes (P0 = origin, R = unit direction, M = centre).
std::optional<ShapeHit> Sphere::intersect(const Ray& ray, Interval t_range) const {
    const Vector3 to_center = center - ray.origin;  // M - P0
    const float m2 = length_squared(to_center);     // 1. m^2; P0 is outside iff m^2 > r^2
    const float r2 = radius * radius;
    const bool outside = m2 > r2;
    const float h = dot(ray.direction, to_center);  // 2. h = R.(M - P0)
    if (outside && h < 0) return std::nullopt;      //    outside and pointing away: no hit
    const Point3 closest = ray.at(h);               // 3. D, the ray point closest to M
    // 4. d^2 = (M - D)^2, measured from D itself: m^2 - h^2 would cancel far from the sphere.
    const float d2 = length_squared(center - closest);
    if (d2 > r2) return std::nullopt;    // 5. the ray passes by
    const float s = std::sqrt(r2 - d2);  // 6. t1 = h - s, t2 = h + s
    const float t1 = h - s, t2 = h + s;
    if (t_range.contains(t1)) return ShapeHit{t1};
    if (t_range.contains(t2)) return ShapeHit{t2};
    return std::nullopt;
}

SurfacePoint Sphere::surface_at(const Ray& ray, const ShapeHit& hit, Uv uv) const {
    // 7. S = P0 + t R and 8. N = (S - M) / r. N is normalised and S projected back onto the
    // sphere, which removes the rounding error of t along the ray.
    const Vector3 unit = normalize(ray.at(hit.t) - center);
    SurfacePoint sp;
    sp.p = center + unit * radius;
    sp.normal = sp.shading_normal = Normal3(unit);
    if (uv == Uv::skip) return sp;
    const float phi = std::atan2(-unit.z, unit.x);
    sp.uv = {(phi < 0 ? phi + 2 * kPi : phi) / (2 * kPi),
             std::acos(std::clamp(-unit.y, -1.0f, 1.0f)) / kPi};
    return sp;
}

}  // namespace glint
