// The right-handed frame around an axis, and the angle around it that the round shapes use as u.
#include "glint/geometry/axis_frame.h"

#include <cmath>

#include "glint/math/constants.h"

namespace glint {

AxisFrame axis_frame(Vector3 unit_axis) {
    Vector3 s, t;
    orthonormal_basis(unit_axis, s, t);
    // orthonormal_basis gives (1, 0, 0) for +y; the cross product makes the frame right-handed.
    return {s, unit_axis, cross(s, unit_axis)};
}

float angle_around(const AxisFrame& frame, Vector3 v) {
    const float phi = std::atan2(-dot(v, frame.z), dot(v, frame.x));
    const float u = (phi < 0 ? phi + 2 * kPi : phi) / (2 * kPi);
    return u < 1 ? u : 0;  // -tiny + 2pi rounds up to 2pi
}

}  // namespace glint
