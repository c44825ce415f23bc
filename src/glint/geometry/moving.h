// A shape that moves while the shutter is open (motion blur): placed by a keyframed transform
// at the time each ray carries. Its bounds hold it over the whole of its motion, so that the
// acceleration structures find it at any time.
#pragma once

#include <memory>
#include <optional>

#include "glint/geometry/surface_point.h"
#include "glint/math/animated_transform.h"
#include "glint/math/bounds.h"
#include "glint/math/interval.h"
#include "glint/math/ray.h"

namespace glint {

struct Shape;

struct Moving {
    Moving(std::shared_ptr<const AnimatedTransform> motion, std::shared_ptr<const Shape> moved);

    std::shared_ptr<const AnimatedTransform> motion;  // world from object; never null
    std::shared_ptr<const Shape> shape;               // never null
    Bounds3 swept;  // the shape's bounds over every time from the first keyframe to the last

    Bounds3 bounds() const { return swept; }
    // As Transformed does, with the transform at ray.time.
    std::optional<ShapeHit> intersect(const Ray& ray, Interval t_range) const;
    SurfacePoint surface_at(const Ray& ray, const ShapeHit& hit, Uv uv = Uv::compute) const;
};

}  // namespace glint
