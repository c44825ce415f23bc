// A pattern's value at a point, through its colour map.
#include "glint/shading/pattern_texture.h"

#include <algorithm>

namespace glint {

Color color_at(const std::vector<ColorStop>& map, float t) {
    // The first stop past t; t on a stop takes the later of two stops there.
    const auto after = std::upper_bound(map.begin(), map.end(), t,
                                        [](float v, const ColorStop& s) { return v < s.at; });
    if (after == map.begin()) return map.front().color;
    if (after == map.end()) return map.back().color;
    const ColorStop& a = *(after - 1);
    const ColorStop& b = *after;
    const float w = (t - a.at) / (b.at - a.at);  // b.at > a.at: upper_bound passed a
    return a.color * (1 - w) + b.color * w;
}

Color evaluate(const PatternTexture& texture, Point3 p) {
    return color_at(texture.colors, pattern_value(texture.spec, texture.to_pattern(p)));
}

}  // namespace glint
