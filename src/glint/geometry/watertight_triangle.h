// The watertight ray/triangle test of Woop, Benthin and Wald (2013): a ray through an edge or a
// vertex that triangles share hits at least one of them, whatever the rounding.
#pragma once

#include <limits>
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

    explicit RayShear(Vector3 direction) {
        const float d[3] = {direction.x, direction.y, direction.z};
        const Vector3 a = abs(direction);
        // kz is the axis of the largest |component| (the first of equals), chosen without
        // branches: incoherent rays would mispredict them.
        const int x_not_less_y = a.x >= a.y, x_not_less_z = a.x >= a.z, y_not_less_z = a.y >= a.z;
        kz = 2 - 2 * (x_not_less_y & x_not_less_z) - ((1 - x_not_less_y) & y_not_less_z);
        constexpr int kNext[3] = {1, 2, 0};
        const int x = kNext[kz], y = kNext[x];
        // Looking down a negative axis mirrors the xy plane; swapping x and y mirrors it back, so
        // that the sign of the determinant still tells the front side (counter-clockwise) from
        // the back.
        const int swap = -int(d[kz] < 0);  // all ones or zero
        kx = x ^ ((x ^ y) & swap);
        ky = y ^ ((x ^ y) & swap);
        // Divided, not multiplied by 1 / d[kz]: one rounding each, the most accurate frame.
        sx = d[kx] / d[kz];
        sy = d[ky] / d[kz];
        sz = 1 / d[kz];
        // An infinite component makes sz zero, and every t with it: poisoned like a NaN
        // direction, such a ray hits nothing.
        if (sz == 0) sx = sy = sz = std::numeric_limits<float>::quiet_NaN();
    }
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
