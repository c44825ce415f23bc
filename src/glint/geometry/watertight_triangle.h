// The watertight ray/triangle test of Woop, Benthin and Wald (2013): a ray through an edge or a
// vertex that triangles share hits at least one of them, whatever the rounding.
#pragma once

#include <optional>

#include "glint/geometry/surface_point.h"
#include "glint/math/interval.h"
#include "glint/math/ray.h"

namespace glint {

// What the test needs of a ray alone: the axes permuted so that z is the direction's largest
// component (x and y swapped when it is negative, to keep the winding), and the shear that maps
// the direction onto (0, 0, 1). Compute it once per ray when testing many triangles.
struct RayShear {
    int kx = 0, ky = 1, kz = 2;
    float sx = 0, sy = 0, sz = 1;

    explicit RayShear(Vector3 direction);
};

// Woop, Benthin and Wald, "Watertight Ray/Triangle Intersection", JCGT 2(1), 2013, on the
// triangle (v0, v1, v2): t within t_range, and the barycentric weights of v1 and v2 as u and v.
// Two-sided. The three edge functions are exact in sign (recomputed in double when the float
// result is 0), so the two triangles that share an edge agree on which side of it the ray
// passes: no ray slips between them. Never hits a triangle of zero area (its edges' float cross
// product is zero), nor with a NaN or an infinity in the ray or the vertices. Whether a hit is
// kept depends on its t alone (t_range.contains(t)). `shear` must be RayShear(ray.direction).
std::optional<ShapeHit> intersect_watertight(Point3 v0, Point3 v1, Point3 v2, const Ray& ray,
                                             const RayShear& shear, Interval t_range);
// The same, shearing the ray on the way (for callers that test one triangle a ray).
std::optional<ShapeHit> intersect_watertight(Point3 v0, Point3 v1, Point3 v2, const Ray& ray,
                                             Interval t_range);

}  // namespace glint
