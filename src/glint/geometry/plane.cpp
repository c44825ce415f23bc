// The notes' ray-plane intersection, the hit point snapped onto the plane, and planar uv.
#include "glint/geometry/plane.h"

namespace glint {

Bounds3 Plane::bounds() const {
    return {{-kInfinity, -kInfinity, -kInfinity}, {kInfinity, kInfinity, kInfinity}};
}

std::optional<ShapeHit> Plane::intersect(const Ray& ray, Interval t_range) const {
    const float n_dot_r = dot(normal, ray.direction);
    if (n_dot_r == 0) return std::nullopt;  // parallel to the plane
    const float d = -dot(normal, to_vector(point));
    const float t = -(d + dot(normal, to_vector(ray.origin))) / n_dot_r;
    if (!t_range.contains(t)) return std::nullopt;
    return ShapeHit{t};
}

SurfacePoint Plane::surface_at(const Ray& ray, const ShapeHit& hit) const {
    SurfacePoint sp;
    const Point3 p = ray.at(hit.t);
    // Remove the error of t along the normal so the point lies on the plane.
    sp.p = p - to_vector(normal) * dot(normal, p - point);
    sp.normal = sp.shading_normal = normal;
    Vector3 s, t;
    orthonormal_basis(to_vector(normal), s, t);
    sp.uv = {dot(sp.p - point, s), dot(sp.p - point, t)};
    sp.dpdu = s;
    sp.dpdv = t;
    sp.has_derivatives = true;
    return sp;
}

}  // namespace glint
