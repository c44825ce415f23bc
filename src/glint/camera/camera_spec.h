// The view as a scene describes it: the notes' view-reference model (look-from, look-at, up)
// and a projection.
#pragma once

#include "glint/math/vector.h"

namespace glint {

enum class Projection { perspective, orthographic };

struct CameraSpec {
    Projection projection = Projection::perspective;
    Point3 from{0, 0, 0};  // the eye
    Point3 at{0, 0, 1};    // the point at the image centre; != from
    Vector3 up{0, 1, 0};   // need not be perpendicular to the view; not parallel to it
    float fov = 45;        // perspective: full vertical field of view, degrees, in (0, 180)
    float height = 2;      // orthographic: height of the view in scene units, > 0
};

}  // namespace glint
