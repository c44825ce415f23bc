// Evaluating a colour source at a surface point: constant, 2D or solid checker, or image lookup.
#include "glint/shading/texture.h"

#include <cmath>
#include <cstdint>

namespace glint {

namespace {

// Parity of one coordinate's cell index; floor() keeps the pattern regular across zero. The
// integer's low bit where it fits in 64 bits (a library call less at every hit); beyond,
// fmod(floor(x), 2), exact for every double and defined where the cast would overflow (huge
// coordinates over tiny squares). NaN counts as even.
bool odd_index(float x, float size) {
    const double cell = std::floor(double(x) / size);
    if (std::abs(cell) < 0x1p62) return (std::int64_t(cell) & 1) != 0;
    return std::abs(std::fmod(cell, 2.0)) == 1.0;
}

bool odd_cell(float a, float b, float c, float size) {
    return (odd_index(a, size) ^ odd_index(b, size) ^ odd_index(c, size)) != 0;
}

struct Evaluate {
    const SurfacePoint& sp;

    Color operator()(const Color& c) const { return c; }
    Color operator()(const CheckerTexture& checker) const {
        const bool odd = checker.space == CheckerSpace::uv
                             ? odd_cell(sp.uv.x, sp.uv.y, 0, checker.size)
                             : odd_cell(sp.p.x, sp.p.y, sp.p.z, checker.size);
        return odd ? checker.odd : checker.even;
    }
    Color operator()(const ImageTexture& image) const { return sample(image, sp.uv, sp.footprint); }
    Color operator()(const NoiseTexture& noise) const { return glint::evaluate(noise, sp.p); }
    Color operator()(const PatternTexturePtr& pattern) const {
        return glint::evaluate(*pattern, sp.p);
    }
    Color operator()(const ProjectedImagePtr& image) const { return glint::evaluate(*image, sp.p); }
    Color operator()(const PigmentMapPtr& map) const { return glint::evaluate(*map, sp); }
};

}  // namespace

Color evaluate(const PigmentMap& map, const SurfacePoint& sp) {
    if (map.average) {
        Color sum{0, 0, 0};
        float weights = 0;
        for (const PigmentMap::Entry& e : map.entries) {
            sum += evaluate(e.texture, sp) * e.at;
            weights += e.at;
        }
        return weights != 0 ? sum * (1 / weights) : Color{0, 0, 0};
    }
    const MapSpan span = span_at(map.entries, pattern_value(map.spec, map.to_pattern(sp.p)));
    const Color lower = evaluate(map.entries[span.lower].texture, sp);
    if (span.weight == 0) return lower;
    return lower * (1 - span.weight) + evaluate(map.entries[span.upper].texture, sp) * span.weight;
}

Color evaluate_pattern(const Texture& texture, const SurfacePoint& sp) {
    return std::visit(Evaluate{sp}, texture);
}

}  // namespace glint
