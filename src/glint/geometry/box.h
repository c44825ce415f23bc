// An axis-aligned box between two corners. A rotated box is a box with a transform.
#pragma once

#include <optional>

#include "glint/geometry/surface_point.h"
#include "glint/geometry/surface_sample.h"
#include "glint/math/bounds.h"
#include "glint/math/interval.h"
#include "glint/math/ray.h"

namespace glint {

struct Box {
    Point3 min{-1, -1, -1};
    Point3 max{1, 1, 1};  // min < max on every axis

    Bounds3 bounds() const { return {min, max}; }
    // Slabs: the box is the intersection of three slabs, so only planes are intersected and no
    // inside test is needed (the notes' "Strahl-Box Schnitt"). hit.part is the face:
    // 2 * axis + (1 on the max side).
    std::optional<ShapeHit> intersect(const Ray& ray, Interval t_range) const;
    // uv: the point's position across the face, in [0,1]^2, along the two other axes in order.
    SurfacePoint surface_at(const Ray& ray, const ShapeHit& hit) const;
    // Its area, and a point drawn uniformly by area from u in [0,1)^2: what lets it light a
    // scene.
    float area() const;
    SurfaceSample sample(Point2 u) const;
};

}  // namespace glint
