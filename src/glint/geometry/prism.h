// A prism: a region of the x-z plane swept straight along y between two heights, POV-Ray's
// prism with linear_sweep and the letters of its text. The region is what closed outlines
// enclose by the even-odd rule, so an outline inside another cuts a hole (the inside of an "o").
// Curved outlines arrive as runs of short edges (append_curve) that keep the curve's normals,
// so a curved wall shades smoothly. A closed solid, unless open (no caps: a tube).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "glint/geometry/surface_point.h"
#include "glint/math/bounds.h"
#include "glint/math/interval.h"
#include "glint/math/ray.h"

namespace glint {

// One straight edge of an outline, in the x-z plane as (x, z), with the directions the outline
// runs at its ends (the curve's tangents; for a straight outline both are b - a).
struct OutlineEdge {
    Point2 a, b;
    Point2 tangent_a, tangent_b;
};

// A closed outline: edges that join end to start, the last back to the first.
using Outline = std::vector<OutlineEdge>;

// Appends the straight edge from a to b (none when they coincide).
void append_line(Outline& outline, Point2 a, Point2 b);

// Appends the curve c(s) = ((A s + B) s + C) s + D, s from 0 to 1 (POV-Ray's splines and
// Bezier curves in power form), as straight edges that stray at most `tolerance` from it: with
// n equal steps of s the gap is at most max|c''| / (8 n^2), and |c''| <= 6|A| + 2|B|.
struct CubicCurve {
    Point2 a, b, c, d;
};
void append_curve(Outline& outline, const CubicCurve& curve, double tolerance);

// The outline with each edge ending exactly where the next starts (the last where the first
// starts, if closed), where they miss by rounding (a curve's end evaluated in power form): a
// gap there would let a ray slip between the walls. Edges that truly part stay apart.
Outline joined(Outline outline, bool closed);

// An edge of an outline, ready for intersection: the outward normals of the edge itself
// (geometric) and of the outline at both ends (for shading). A prism's edges and a lathe's
// pieces.
struct OrientedEdge {
    Point2 a, b;
    Point2 normal, normal_a, normal_b;
};
using PrismEdge = OrientedEdge;

// Edges in runs of kPrismGroup along the outlines, each run with its box: a ray or an inside
// test skips a run whose box it misses. Outlines are coherent, so runs are compact.
inline constexpr std::size_t kPrismGroup = 8;
struct PrismProfile {
    std::vector<PrismEdge> edges;
    std::vector<Point2> group_min, group_max;  // one per run of kPrismGroup edges
    Point2 min, max;
};

struct Prism {
    // Build with make_prism().
    std::shared_ptr<const PrismProfile> profile;  // never null once made
    float bottom = 0, top = 1;                    // heights along y, bottom < top
    bool open = false;                            // without the caps at bottom and top

    Bounds3 bounds() const;
    // The caps (planes y = bottom and top, where the hit point is inside the outlines by the
    // even-odd crossing count) and the walls (each edge swept from bottom to top: the ray's
    // shadow on the x-z plane against the edge, in double), the nearest in range.
    std::optional<ShapeHit> intersect(const Ray& ray, Interval t_range) const;
    // Normals point out of the solid; a wall's shading normal runs between the outline's normals
    // at the edge's ends. uv: (x, z) on the caps; on a wall, the place along the edge (0 to 1)
    // and the height from bottom (0) to top (1).
    SurfacePoint surface_at(const Ray& ray, const ShapeHit& hit) const;
};

// Whether (x, z) is inside the outlines, by the even-odd rule.
bool inside_profile(const PrismProfile& profile, double x, double z);

// Orients every edge's normals out of the region and groups the edges. An error when the
// outlines are empty or not finite, bottom >= top, or the region has no area.
std::variant<Prism, std::string> make_prism(const std::vector<Outline>& outlines, float bottom,
                                            float top, bool open = false);

}  // namespace glint
