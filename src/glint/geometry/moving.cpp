// A moving shape: the transform of the ray's moment, then the placed shape's own tests.
#include "glint/geometry/moving.h"

#include <utility>

#include "glint/geometry/shape.h"

namespace glint {

Moving::Moving(std::shared_ptr<const AnimatedTransform> m, std::shared_ptr<const Shape> moved)
    : motion(std::move(m)), shape(std::move(moved)) {
    const Bounds3 b = glint::bounds(*shape);
    swept = b.is_finite()
                ? motion->motion_bounds(b, motion->start_time(), motion->end_time())
                : Bounds3{{-kInfinity, -kInfinity, -kInfinity}, {kInfinity, kInfinity, kInfinity}};
}

std::optional<ShapeHit> Moving::intersect(const Ray& ray, Interval t_range) const {
    return intersect_placed(*shape, motion->at(ray.time), ray, t_range);
}

SurfacePoint Moving::surface_at(const Ray& ray, const ShapeHit& hit, Uv uv) const {
    return surface_at_placed(*shape, motion->at(ray.time), ray, hit, uv);
}

}  // namespace glint
