// Parts the render tests build their scenes from: a material that only glows, and a polygon from
// its corners.
#pragma once

#include <utility>
#include <vector>

#include "glint/geometry/polygon.h"
#include "glint/shading/material.h"

namespace glint::testing {

// Emits c and reflects nothing: its pixels are c wherever it is seen, whatever the lights.
inline Material glowing(Color c) {
    Material m;
    m.ka = m.kd = m.ks = 0;
    m.emission = c;
    return m;
}

// The corners must make a valid polygon (make_polygon).
inline Polygon polygon(std::vector<Point3> corners) {
    return std::get<Polygon>(make_polygon(std::move(corners), InsideTest::even_odd));
}

}  // namespace glint::testing
