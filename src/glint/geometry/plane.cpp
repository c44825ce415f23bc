// The hit point snapped onto the plane, and planar uv (the notes' intersection: plane.h, inline).
#include "glint/geometry/plane.h"

namespace glint {

Bounds3 Plane::bounds() const {
    return {{-kInfinity, -kInfinity, -kInfinity}, {kInfinity, kInfinity, kInfinity}};
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
