// A sphere given by centre and radius.
#pragma once

#include <optional>

#include "glint/geometry/surface_point.h"
#include "glint/geometry/surface_sample.h"
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
    // Its area, and a point drawn uniformly by area from u in [0,1)^2: what lets it light a
    // scene.
    float area() const;
    SurfaceSample sample(Point2 u) const;
    // A point drawn for lighting the point `from`: uniformly over the cone of directions the
    // sphere fills as seen from there, the near side along it, which draws no point on its hidden
    // side and keeps the points near it from flickering; from inside or on it, sample(u). The pdf
    // is per unit area either way.
    SurfaceSample sample_seen_from(Point3 from, Point2 u) const;
    // The density per unit area with which sample_seen_from(from, u) draws the point q of it: for
    // multiple importance sampling, which weighs a point found another way by it.
    float pdf_seen_from(Point3 from, Point3 q) const;
};

}  // namespace glint
