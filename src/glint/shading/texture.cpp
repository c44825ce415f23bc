// Evaluating a colour source at a surface point: constant, 2D or solid checker, image lookup,
// pattern, pigment map or layers.
#include "glint/shading/texture.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "glint/shading/pattern.h"

namespace glint {

namespace {

// Parity of one coordinate's cell index (checker_cell: regular across zero, firm on the cells'
// boundaries). The integer's low bit where it fits in 64 bits (a library call less at every
// hit); beyond, fmod(cell, 2), exact for every double and defined where the cast would overflow
// (huge coordinates over tiny squares). NaN counts as even.
bool odd_index(float x, float size) {
    const double cell = checker_cell(double(x) / size);
    if (std::abs(cell) < 0x1p62) return (std::int64_t(cell) & 1) != 0;
    return std::abs(std::fmod(cell, 2.0)) == 1.0;
}

bool odd_cell(float a, float b, float c, float size) {
    return (odd_index(a, size) ^ odd_index(b, size) ^ odd_index(c, size)) != 0;
}

// Where a pattern laid over the surface's uv lies: (u, v, 0).
Point3 uv_point(const SurfacePoint& sp) { return {sp.uv.x, sp.uv.y, 0}; }

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
        return glint::evaluate(*pattern, pattern->uv_mapping ? uv_point(sp) : sp.p);
    }
    Color operator()(const ProjectedImagePtr& image) const { return glint::evaluate(*image, sp.p); }
    Color operator()(const PigmentMapPtr& map) const { return glint::evaluate(*map, sp); }
    Color operator()(const LayeredTexturePtr& layered) const {
        return glint::evaluate(*layered, sp);
    }
};

}  // namespace

namespace {

// The map's colour at sp, the point where its pattern and entries are evaluated.
Color evaluate_entries(const PigmentMap& map, const SurfacePoint& sp) {
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

}  // namespace

Color evaluate(const PigmentMap& map, const SurfacePoint& at) {
    if (!map.uv_mapping) [[likely]]
        return evaluate_entries(map, at);
    // Laid over the uv, the map and its entries see the point (u, v, 0).
    SurfacePoint on_uv = at;
    on_uv.p = uv_point(at);
    return evaluate_entries(map, on_uv);
}

LayeredColors evaluate_layers(const LayeredTexture& layered, const SurfacePoint& sp) {
    LayeredColors sum{{0, 0, 0}, {0, 0, 0}};
    Color passed{1, 1, 1};  // what the layers above let through
    for (const LayeredTexture::Layer& layer : layered.layers) {
        const Color c = evaluate(layer.color, sp);
        const Color ft = evaluate(layer.filter_transmit, sp);
        const float filter = ft.r, transmit = ft.g;
        const float opacity = layered.legacy_opacity
                                  ? 1 - (filter * std::max({c.r, c.g, c.b}) + transmit)
                                  : 1 - filter - transmit;
        const Color seen = passed * c * opacity;
        sum.diffuse += seen * layer.diffuse;
        sum.ambient += seen * layer.ambient;
        passed = passed * (c * filter + Color::gray(transmit));
        if (passed.r <= 0 && passed.g <= 0 && passed.b <= 0) break;
    }
    return sum;
}

Uv uv_needed_inside(const Texture& texture) {
    const auto* checker = std::get_if<CheckerTexture>(&texture);
    if ((checker && checker->space == CheckerSpace::uv) ||
        std::holds_alternative<ImageTexture>(texture))
        return Uv::compute;
    if (const auto* pattern = std::get_if<PatternTexturePtr>(&texture))
        if ((*pattern)->uv_mapping) return Uv::compute;
    if (const auto* map = std::get_if<PigmentMapPtr>(&texture)) {
        if ((*map)->uv_mapping) return Uv::compute;
        for (const PigmentMap::Entry& e : (*map)->entries)
            if (uv_needed(e.texture) == Uv::compute) return Uv::compute;
    }
    if (const auto* layered = std::get_if<LayeredTexturePtr>(&texture))
        for (const LayeredTexture::Layer& layer : (*layered)->layers)
            if (uv_needed(layer.color) == Uv::compute ||
                uv_needed(layer.filter_transmit) == Uv::compute)
                return Uv::compute;
    return Uv::skip;
}

Color evaluate_pattern(const Texture& texture, const SurfacePoint& sp) {
    return std::visit(Evaluate{sp}, texture);
}

}  // namespace glint
