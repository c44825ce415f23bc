// A sphere swept along a curve, its radius changing on the way (POV-Ray's sphere_sweep), as a
// chain of glint's own solids: a sphere at each joint and, between two joints, the cone frustum
// tangent to both spheres. Their merge is the swept solid exactly for a straight path
// (linear_spline), and within a tolerance for a curved one, whose segments are cut into
// straight pieces until the curve strays from each piece's chord by less than it.
#pragma once

#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "glint/geometry/cone.h"
#include "glint/geometry/sphere.h"

namespace glint {

enum class SweepSpline {
    linear,    // straight from each sphere to the next
    b_spline,  // the uniform cubic B-spline of the spheres: near them, through none
    cubic,     // Catmull-Rom's: through the spheres from the second to the last but one
};

struct SweptSphere {
    Point3 center;
    float radius = 1;  // > 0
};

// The chain's solids. A cone is missing between two spheres of which one holds the other.
struct SweepPieces {
    std::vector<Sphere> spheres;
    std::vector<Cone> cones;
};

// The point of the curve in segment `segment` at t in [0, 1]: the centre and radius (x, y, z,
// r) blended from spheres segment .. segment + 3 of a cubic spline by its basis, or from
// segment .. segment + 1 of a linear one.
SweptSphere sweep_at(SweepSpline spline, const std::vector<SweptSphere>& spheres,
                     std::size_t segment, float t);

// The capped cone tangent to both spheres (from a's side to b's), where neither holds the
// other. With d the centres' distance and sin(alpha) = (ra - rb) / d, it touches sphere a on
// the circle at ra sin(alpha) along the axis from a's centre, of radius ra cos(alpha), and b
// at d + rb sin(alpha), of radius rb cos(alpha).
std::optional<Cone> tangent_cone(const SweptSphere& a, const SweptSphere& b);

// The pieces of the sweep through `spheres` (at least 2 for linear, 4 for the cubic splines),
// each curved segment cut until it strays from a chord by at most `tolerance` times the smaller
// radius of its ends (and into at most 256 pieces). Else what is wrong, e.g.
// "sphere_sweep b_spline needs at least 4 spheres, got 3".
std::variant<SweepPieces, std::string> sweep_pieces(SweepSpline spline,
                                                    const std::vector<SweptSphere>& spheres,
                                                    float tolerance = 1e-3f);

}  // namespace glint
