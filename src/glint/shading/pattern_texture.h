// A solid pattern through a colour map, placed in the scene by its own transform: POV-Ray's
// pigment { gradient y color_map { ... } scale 2 }.
#pragma once

#include <cstddef>
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

// Where t falls on a map sorted by `at` (at least one stop): the stops either side and the
// weight of the upper one. Below the first stop and above the last, both are that stop; t on a
// stop takes the later of two stops there.
struct MapSpan {
    std::size_t lower = 0, upper = 0;
    float weight = 0;
};

template <class Stop>
MapSpan span_at(const std::vector<Stop>& map, double t) {
    std::size_t upper = 0;  // the first stop past t
    while (upper < map.size() && !(t < map[upper].at)) ++upper;
    if (upper == 0) return {};
    if (upper == map.size()) return {upper - 1, upper - 1, 0};
    const auto& a = map[upper - 1];
    const auto& b = map[upper];  // b.at > a.at: t lies in [a.at, b.at)
    return {upper - 1, upper, float((t - a.at) / (b.at - a.at))};
}

// The colour the map gives the value t: stops sorted by `at`, at least one.
Color color_at(const std::vector<ColorStop>& map, float t);

struct PatternTexture {
    PatternSpec spec;
    std::vector<ColorStop> colors;  // sorted by `at`, at least one
    Transform to_pattern;           // scene space (or uv space) to the pattern's
    // The pattern laid over the surface's uv, at (u, v, 0), instead of its point in space
    // (POV-Ray's uv_mapping).
    bool uv_mapping = false;
};

Color evaluate(const PatternTexture& texture, Point3 p);

}  // namespace glint
