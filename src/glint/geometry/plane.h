// An infinite plane through a point with a unit normal.
#pragma once

#include <optional>

#include "glint/geometry/surface_point.h"
#include "glint/math/bounds.h"
#include "glint/math/interval.h"
#include "glint/math/ray.h"

namespace glint {

struct Plane {
    Point3 point;
    Normal3 normal{0, 1, 0};  // unit length

    // Infinite: an empty box with infinite corners would be lost in a union, so the bounds are
    // the whole space. Acceleration structures keep unbounded shapes apart.
    Bounds3 bounds() const;
    // t = -(D + N.P0) / (N.R) with D = -N.point (the notes' ray-polygon plane step).
    std::optional<ShapeHit> intersect(const Ray& ray, Interval t_range) const {
        const float n_dot_r = dot(normal, ray.direction);
        if (n_dot_r == 0) return std::nullopt;  // parallel to the plane
        const float d = -dot(normal, to_vector(point));
        const float t = -(d + dot(normal, to_vector(ray.origin))) / n_dot_r;
        if (!t_range.contains(t)) return std::nullopt;
        return ShapeHit{t};
    }
    // uv: world-unit coordinates along two perpendicular directions in the plane.
    SurfacePoint surface_at(const Ray& ray, const ShapeHit& hit) const;
};

}  // namespace glint
