// The German lecture notes' geometric ray-sphere method, step by step with its early exits, and
// the sphere's normal and spherical uv.
#include "glint/geometry/sphere.h"

#include <algorithm>
#include <cmath>

#include "glint/math/constants.h"
#include "glint/sampling/warp.h"

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
    // p = c + r (sin(pi v) cos(phi), -cos(pi v), -sin(pi v) sin(phi)) with phi = 2 pi u, and
    // the normal moves with the point: dn = dp / r. At the poles dp/du vanishes.
    const float rho = std::max(std::sqrt(unit.x * unit.x + unit.z * unit.z), 1e-6f);
    sp.dpdu = Vector3{unit.z, 0, -unit.x} * (2 * kPi * radius);
    sp.dpdv = Vector3{-unit.y * unit.x / rho, rho, -unit.y * unit.z / rho} * (kPi * radius);
    sp.dndu = sp.dpdu / radius;
    sp.dndv = sp.dpdv / radius;
    sp.has_derivatives = true;
    return sp;
}

float Sphere::area() const { return 4 * kPi * radius * radius; }

SurfaceSample Sphere::sample(Point2 u) const {
    const Vector3 d = sample_uniform_sphere(u);
    return {center + d * radius, Normal3(d), 1 / area()};
}

namespace {

// Whether `from` lies far enough outside the sphere for it to fill a cone of directions there.
bool sees_a_cone(const Sphere& s, Point3 from) {
    return length_squared(s.center - from) > s.radius * s.radius * 1.0001f;
}

// 1 - cos of the half-angle of that cone, written so that it keeps its digits when the sphere
// looks small: sin^2 / (1 + cos).
float one_minus_cos_max(const Sphere& s, Point3 from) {
    const float sin2_max = s.radius * s.radius / length_squared(s.center - from);
    return sin2_max / (1 + std::sqrt(1 - sin2_max));
}

}  // namespace

SurfaceSample Sphere::sample_seen_from(Point3 from, Point2 u) const {
    if (!sees_a_cone(*this, from)) return sample(u);
    const Vector3 to_center = center - from;
    const float d2 = length_squared(to_center), r2 = radius * radius;
    const float d = std::sqrt(d2);
    const float cos_max = std::sqrt(1 - r2 / d2);
    const Vector3 w = from_frame(sample_uniform_cone(u, cos_max), to_center / d);
    // The near point along w, from the distance of the line to the centre measured directly.
    const float b = dot(w, to_center);
    const float t = b - std::sqrt(std::max(0.0f, r2 - length_squared(to_center - w * b)));
    const Point3 p = from + w * t;
    const Vector3 normal = normalize(p - center);
    // pdf by solid angle 1 / (2 pi (1 - cos_max)), turned into one by area.
    const float cos_at_point = std::abs(dot(normal, w));
    return {p, Normal3(normal), cos_at_point / (2 * kPi * one_minus_cos_max(*this, from) * t * t)};
}

float Sphere::pdf_seen_from(Point3 from, Point3 q) const {
    if (!sees_a_cone(*this, from)) return 1 / area();
    const Vector3 w = q - from;
    const float t2 = length_squared(w);
    if (!(t2 > 0)) return 0;
    const float cos_at_point = std::abs(dot(normalize(q - center), w)) / std::sqrt(t2);
    return cos_at_point / (2 * kPi * one_minus_cos_max(*this, from) * t2);
}

}  // namespace glint
