// A ring torus around an axis through its centre: a tube of radius minor_radius whose centre runs
// on a circle of radius major_radius. A closed solid.
#pragma once

#include <optional>
#include <string>

#include "glint/geometry/surface_point.h"
#include "glint/math/bounds.h"
#include "glint/math/interval.h"
#include "glint/math/ray.h"

namespace glint {

struct Torus {
    Point3 center;
    Normal3 axis{0, 1, 0};       // unit (other non-zero lengths are normalised)
    float major_radius = 1;      // centre of the tube from the axis, > minor_radius
    float minor_radius = 0.25f;  // tube radius, > 0

    // Tight: the circle of the tube's centre (extent R sqrt(1 - a_i^2) along world axis i)
    // grown by the tube radius.
    Bounds3 bounds() const;
    // The torus (|P|^2 + R^2 - r^2)^2 = 4 R^2 |P - (P.a) a|^2, with P relative to the centre,
    // along the ray is a quartic in t, solved by solve_quartic in double. For accuracy the ray's
    // origin is first moved along it to the point nearest the centre (near_ray of disk.h), inside
    // the bounding sphere when the ray can hit at all, so the coefficients are of the torus' size
    // however far away the ray starts; each root is then polished by a Newton step on the torus
    // function itself. A ray tangent to the tube gives a double root and counts as a hit.
    std::optional<ShapeHit> intersect(const Ray& ray, Interval t_range) const;
    // The point is projected onto the tube; the normal points out of the tube (away from the
    // tube's centre circle). uv are the torus angles / 2pi, each in [0, 1): u around the axis
    // (axis_frame(axis) of disk.h: for the axis +y, from +x towards -z like the sphere's
    // longitude), v around the tube, 0 on the outer equator and 0.25 on the top (the +axis side).
    SurfacePoint surface_at(const Ray& ray, const ShapeHit& hit) const;
};

// Empty when the torus is valid, else what is wrong, e.g.
// "torus major_radius must be > minor_radius, got 0.5 and 1".
std::string describe_problem(const Torus& torus);

}  // namespace glint
