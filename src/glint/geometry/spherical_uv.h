// Texture coordinates from the direction of a point seen from a centre: the sphere's mapping,
// for shapes without a natural parametrisation (implicit surfaces, fractals).
#pragma once

#include <algorithm>
#include <cmath>

#include "glint/math/constants.h"
#include "glint/math/vector.h"

namespace glint {

// u = longitude / 2pi around +y from +x (counter-clockwise seen from above), v = latitude from
// the south pole (0) to the north pole (1). The centre itself maps to the north pole.
inline Point2 spherical_uv(Point3 p, Point3 center) {
    const Vector3 d = p - center;
    const float l = length(d);
    const Vector3 unit = l > 0 ? d / l : Vector3{0, 1, 0};
    const float phi = std::atan2(-unit.z, unit.x);
    return {(phi < 0 ? phi + 2 * kPi : phi) / (2 * kPi),
            std::acos(std::clamp(-unit.y, -1.0f, 1.0f)) / kPi};
}

}  // namespace glint
