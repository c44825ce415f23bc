// Intersecting a transformed shape in its own space: the ray goes to object space (t rescaled, as
// the direction is renormalised) and the surface point comes back to world space.
#include "glint/geometry/transformed.h"

#include <cmath>

#include "glint/geometry/shape.h"

namespace glint {

ObjectRay to_object(const Transform& world_from_object, const Ray& ray) {
    const Transform object_from_world = world_from_object.inverse();
    const Vector3 d = object_from_world(ray.direction);
    const float scale = length(d);
    return {{object_from_world(ray.origin), d / scale, ray.time, ray.wavelength}, scale};
}

Bounds3 Transformed::bounds() const {
    const Bounds3 b = glint::bounds(*shape);
    if (!b.is_finite()) {
        return {{-kInfinity, -kInfinity, -kInfinity}, {kInfinity, kInfinity, kInfinity}};
    }
    return world_from_object()(b);
}

std::optional<ShapeHit> Transformed::intersect(const Ray& ray, Interval t_range) const {
    return intersect_placed(*shape, world_from_object(), ray, t_range);
}

SurfacePoint Transformed::surface_at(const Ray& ray, const ShapeHit& hit, Uv uv) const {
    return surface_at_placed(*shape, world_from_object(), ray, hit, uv);
}

std::optional<ShapeHit> intersect_placed(const Shape& shape, const Transform& world_from_object,
                                         const Ray& ray, Interval t_range) {
    const ObjectRay o = to_object(world_from_object, ray);
    Interval object_range{t_range.min * o.scale, t_range.max * o.scale};
    // Rounding in the two scalings must not move the hit outside the caller's range. A hit that
    // lands just before it is the one the caller has (a CSG walk asks for the crossing after
    // the last): the next one is looked for beyond it, rather than lost.
    for (int attempt = 0; attempt < 4; ++attempt) {
        auto hit = glint::intersect(shape, o.ray, object_range);
        if (!hit) return std::nullopt;
        const float t = hit->t / o.scale;
        if (t > t_range.max || !(t == t)) return std::nullopt;
        if (t >= t_range.min) {
            hit->t = t;
            return hit;
        }
        object_range.min = std::nextafter(hit->t, kInfinity);
    }
    return std::nullopt;
}

SurfacePoint surface_at_placed(const Shape& shape, const Transform& world_from_object,
                               const Ray& ray, const ShapeHit& hit, Uv uv) {
    const ObjectRay o = to_object(world_from_object, ray);
    ShapeHit object_hit = hit;
    object_hit.t = hit.t * o.scale;
    SurfacePoint sp = glint::surface_at(shape, o.ray, object_hit, uv);
    sp.p = world_from_object(sp.p);
    sp.normal = normalize(world_from_object(sp.normal));
    const Vector3 m = to_vector(world_from_object(sp.shading_normal));
    sp.shading_normal = Normal3(normalize(m));
    if (sp.has_derivatives) {
        sp.dpdu = world_from_object(sp.dpdu);
        sp.dpdv = world_from_object(sp.dpdv);
        // The normal is m / |m| with m = M^-T n: its change is M^-T dn less its part along the
        // normal, over |m|.
        const Vector3 n = to_vector(sp.shading_normal);
        const float inverse_length = 1 / length(m);
        auto normal_change = [&](Vector3 dn) {
            const Vector3 dm = to_vector(world_from_object(Normal3(dn)));
            return (dm - n * dot(n, dm)) * inverse_length;
        };
        sp.dndu = normal_change(sp.dndu);
        sp.dndv = normal_change(sp.dndv);
    }
    return sp;
}

}  // namespace glint
