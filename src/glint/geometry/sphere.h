// A sphere given by centre and radius.
#pragma once

#include <optional>

#include "glint/geometry/surface_point.h"
#include "glint/math/bounds.h"
#include "glint/math/interval.h"
#include "glint/math/ray.h"

namespace glint {

struct Sphere {
    Point3 center;
    float radius = 1;  // > 0

    Bounds3 bounds() const;
    // The geometric method of the lecture notes, with its early exits. Needs a unit direction.
    std::optional<ShapeHit> intersect(const Ray& ray, Interval t_range) const;
    // uv: u = longitude / 2pi around +y from +x, v = latitude from the south pole (0) to the
    // north pole (1).
    SurfacePoint surface_at(const Ray& ray, const ShapeHit& hit, Uv uv = Uv::compute) const;
};

}  // namespace glint
