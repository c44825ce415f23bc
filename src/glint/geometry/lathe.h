// A lathe: a curve in the (r, y) half-plane turned round the y axis, POV-Ray's lathe. Each
// straight piece of the curve turns into a cone frustum (a flat ring where it runs across the
// axis, a cylinder where it runs along it), met by a quadratic in t; curves arrive as runs of
// short pieces (append_curve of prism.h) that keep the curve's normals, so the surface shades
// smoothly. A closed curve makes a closed solid.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "glint/geometry/prism.h"
#include "glint/geometry/surface_point.h"
#include "glint/math/bounds.h"
#include "glint/math/interval.h"
#include "glint/math/ray.h"

namespace glint {

// A piece of the curve in the (r, y) plane, with the normals (r, y) of the piece and of the
// curve at its ends, pointing out of the solid where the curve is closed.
using LathePiece = OrientedEdge;

// Pieces in runs of kLatheGroup along the curve, each run with its reach from the axis and its
// heights: a ray skips a run whose cylinder it misses.
inline constexpr std::size_t kLatheGroup = 8;
struct LatheProfile {
    std::vector<LathePiece> pieces;
    std::vector<float> group_radius, group_bottom, group_top;  // one per run
    float radius = 0, bottom = 0, top = 0;                     // of the whole curve
};

struct Lathe {
    // Build with make_lathe().
    std::shared_ptr<const LatheProfile> profile;  // never null once made
    bool closed = false;                          // the curve returns to its start: a solid

    Bounds3 bounds() const;
    // Each piece's surface x^2 + z^2 = r(y)^2, r linear in y along the piece, a quadratic in t
    // solved in double; a piece across the axis (constant y) is a plane ring. The nearest hit in
    // range whose height (or radius) lies on the piece.
    std::optional<ShapeHit> intersect(const Ray& ray, Interval t_range) const;
    // The normal is the piece's (r, y) normal turned to the hit's side of the axis; the shading
    // normal runs between the curve's normals at the piece's ends. uv: the angle round y over a
    // turn (from +x towards -z), and the place along the curve (0 to 1 over its pieces).
    SurfacePoint surface_at(const Ray& ray, const ShapeHit& hit) const;
};

// The lathe of an open or closed curve in the (r, y) plane (r may be negative: x^2 + z^2 = r^2
// turns it the same as -r). A closed curve's normals point out of the region it encloses, an
// open one's to the right of the way it runs. An error when the curve is empty or not finite.
std::variant<Lathe, std::string> make_lathe(const Outline& curve);

}  // namespace glint
