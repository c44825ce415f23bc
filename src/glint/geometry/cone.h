// A truncated cone (frustum) between two circular ends, pointed when one radius is zero; the NFF
// `c` primitive. Open (a lamp shade) or capped (a solid).
#pragma once

#include <optional>
#include <string>

#include "glint/geometry/surface_point.h"
#include "glint/math/bounds.h"
#include "glint/math/interval.h"
#include "glint/math/ray.h"

namespace glint {

struct Cone {
    Point3 base;
    float base_radius = 1;  // >= 0
    Point3 apex;            // the other end's centre, != base
    float apex_radius = 0;  // >= 0, not both radii 0; 0 gives a pointed cone
    bool capped = false;    // closed by disks at the ends with a non-zero radius

    // The union of the two end disks' bounds.
    Bounds3 bounds() const;
    // In the frame of the axis a (unit, base to apex), with y = P.a measured from the axis'
    // midpoint and h half the length, the radius is rho(y) = r_mid + k y with k = (apex_radius -
    // base_radius) / 2h. The side is |P - y a|^2 = rho(y)^2, a quadratic in t, kept where
    // |y| <= h (there rho >= 0, so the mirrored nappe past a pointed apex is cut off). The caps
    // are disks. hit.part: 0 side, 1 base cap, 2 apex cap.
    std::optional<ShapeHit> intersect(const Ray& ray, Interval t_range) const;
    // Side: the normal is the gradient direction (radial - k a) / sqrt(1 + k^2), outward (also
    // when open); at a pointed apex, where radial is undefined, that of the frame's x. u is the
    // angle around the axis / 2pi in [0, 1) (axis_frame(a) of disk.h), v = height / length in
    // [0, 1] from the base. Caps: the normal is -a at the base and +a at the apex end; u the same
    // angle, v = distance from the axis / the cap's radius.
    SurfacePoint surface_at(const Ray& ray, const ShapeHit& hit) const;
};

// Empty when the cone is valid, else what is wrong, e.g.
// "cone base_radius must be >= 0, got -1".
std::string describe_problem(const Cone& cone);

}  // namespace glint
