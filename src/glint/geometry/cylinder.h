// A finite circular cylinder between two end centres, open (a tube) or capped (a solid).
#pragma once

#include <optional>
#include <string>

#include "glint/geometry/surface_point.h"
#include "glint/geometry/surface_sample.h"
#include "glint/math/bounds.h"
#include "glint/math/interval.h"
#include "glint/math/ray.h"

namespace glint {

struct Cylinder {
    Point3 base;
    Point3 top;           // != base
    float radius = 1;     // > 0
    bool capped = false;  // closed by disks at both ends: a solid (usable in CSG)

    // The union of the two end disks' bounds.
    Bounds3 bounds() const;
    // In the frame of the axis a (unit, base to top), with P relative to the axis' midpoint:
    // the side is |P - (P.a) a|^2 = radius^2, a quadratic in t, kept where |P.a| <= half the
    // length; the caps are disks. hit.part: 0 side, 1 base cap, 2 top cap.
    std::optional<ShapeHit> intersect(const Ray& ray, Interval t_range) const;
    // Side: the normal points away from the axis (outward, also when open); u is the angle
    // around the axis / 2pi in [0, 1) (axis_frame(a) of disk.h: for an axis along +y, from +x
    // towards -z like the sphere's longitude), v = height / length in [0, 1] from the base.
    // Caps: the normal is -a at the base and +a at the top; u the same angle, v = distance from
    // the axis / radius.
    SurfacePoint surface_at(const Ray& ray, const ShapeHit& hit) const;
    // Its area (the caps' too when capped), and a point drawn uniformly by area from u in
    // [0,1)^2: what lets it light a scene.
    float area() const;
    SurfaceSample sample(Point2 u) const;
};

// Empty when the cylinder is valid, else what is wrong, e.g.
// "cylinder radius must be > 0, got 0".
std::string describe_problem(const Cylinder& cylinder);

}  // namespace glint
