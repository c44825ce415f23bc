// A point drawn on a shape's surface: what the shapes that can light a scene return from their
// sample(u), uniformly by area.
#pragma once

#include "glint/math/vector.h"

namespace glint {

struct SurfaceSample {
    Point3 p;
    Normal3 normal;  // unit, the shape's geometric normal there
    float pdf = 0;   // density per unit area at p
};

}  // namespace glint
