// A flat disk, optionally with a hole (an annulus), and the bounds of a tilted disk that the
// round shapes' caps share.
#pragma once

#include <optional>
#include <string>

#include "glint/geometry/surface_point.h"
#include "glint/geometry/surface_sample.h"
#include "glint/math/bounds.h"
#include "glint/math/interval.h"
#include "glint/math/ray.h"

namespace glint {

struct Disk {
    Point3 center;
    Normal3 normal{0, 1, 0};  // unit; the front side (other non-zero lengths are normalised)
    float radius = 1;         // > 0
    float inner_radius = 0;   // in [0, radius)

    // Tight: the disk's extent along world axis i is radius * sqrt(1 - n_i^2).
    Bounds3 bounds() const;
    // The plane t = N.(C - P0) / N.R (the notes' ray-plane step), then
    // inner_radius <= |P - C| <= radius. Two-sided.
    std::optional<ShapeHit> intersect(const Ray& ray, Interval t_range) const;
    // normal: `normal`, whichever side the ray came from. uv (polar): u is the angle around the
    // normal (axis_frame(normal), see below) / 2pi in [0, 1); v runs from the inner edge (the
    // centre when there is no hole) at 0 to the rim at 1.
    SurfacePoint surface_at(const Ray& ray, const ShapeHit& hit) const;
    // Its area, and a point drawn uniformly by area from u in [0,1)^2: what lets it light a
    // scene.
    float area() const;
    SurfaceSample sample(Point2 u) const;
};

// Empty when the disk is valid, else what is wrong, e.g. "disk radius must be > 0, got -1".
std::string describe_problem(const Disk& disk);

// The bounds of a disk; extents use sqrt(n_j^2 + n_k^2) / |n| for sqrt(1 - n_i^2), which does not
// cancel when the normal is nearly along axis i.
Bounds3 disk_bounds(Point3 center, Vector3 normal, float radius);

}  // namespace glint
