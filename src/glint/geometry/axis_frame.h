// The frame around an axis in which the round shapes (disk, cylinder, cone, torus) measure their
// texture angle.
#pragma once

#include "glint/math/vector.h"

namespace glint {

// Right-handed (x, axis, z) around a unit axis; for the axis +y it is the world's (x, y, z).
// Texture angles around an axis run from x towards -z, counter-clockwise seen from the axis'
// tip: for the axis +y, as the sphere's longitude does.
struct AxisFrame {
    Vector3 x, axis, z;
};
AxisFrame axis_frame(Vector3 unit_axis);
// The angle of v around the frame's axis, from x towards -z, / 2pi: in [0, 1).
float angle_around(const AxisFrame& frame, Vector3 v);

}  // namespace glint
