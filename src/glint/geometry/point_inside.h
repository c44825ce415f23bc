// Whether a point lies inside a closed solid, by counting the surface's crossings along rays
// from it (the Jordan curve theorem's parity): for checks of a scene, not for rendering.
#pragma once

#include <optional>

#include "glint/geometry/shape.h"

namespace glint {

// Inside when a ray from p crosses the surface an odd number of times. Three rays in unrelated
// directions vote, so that one that grazes an edge or a silhouette (a crossing counted twice, or
// not at all) is outvoted. Nothing for a shape that is not a bounded closed solid (is_solid()
// with finite bounds: a plane's half-space, an open mesh or a disk has no inside to ask about).
// A point on the surface may count either way.
std::optional<bool> point_inside(const Shape& shape, Point3 p);

}  // namespace glint
