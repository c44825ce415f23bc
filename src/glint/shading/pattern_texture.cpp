// A pattern's value at a point, through its colour map.
#include "glint/shading/pattern_texture.h"

namespace glint {

Color color_at(const std::vector<ColorStop>& map, float t) {
    const MapSpan span = span_at(map, t);
    return map[span.lower].color * (1 - span.weight) + map[span.upper].color * span.weight;
}

Color evaluate(const PatternTexture& texture, Point3 p) {
    return color_at(texture.colors, pattern_value(texture.spec, texture.to_pattern(p)));
}

}  // namespace glint
