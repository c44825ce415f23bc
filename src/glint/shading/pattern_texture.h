// A solid pattern through a colour map, placed in the scene by its own transform: POV-Ray's
// pigment { gradient y color_map { ... } scale 2 }.
#pragma once

#include <vector>

#include "glint/math/color.h"
#include "glint/math/transform.h"
#include "glint/shading/pattern.h"

namespace glint {

// The colour at `at` on a colour map. Between two stops the colour is linear; below the first
// it is the first's, above the last the last's; two stops at one place make a sharp edge.
struct ColorStop {
    float at = 0;
    Color color;
};

// The colour the map gives the value t: stops sorted by `at`, at least one.
Color color_at(const std::vector<ColorStop>& map, float t);

struct PatternTexture {
    PatternSpec spec;
    std::vector<ColorStop> colors;  // sorted by `at`, at least one
    Transform to_pattern;           // scene space to the pattern's
};

Color evaluate(const PatternTexture& texture, Point3 p);

}  // namespace glint
