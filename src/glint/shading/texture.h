// Colour sources for materials: a constant colour, a checker pattern, either painted on the
// surface's uv coordinates (2D) or carved out of space (3D, a solid texture), an image on the
// surface's uv or projected through space, a noise pattern through a colour ramp (solid), one
// of POV-Ray's patterns through a colour map (solid, placed by its own transform), or such a
// pattern choosing between other colour sources (POV-Ray's pigment_map), or colour sources
// stacked in layers that let what lies below show through (POV-Ray's layered textures).
#pragma once

#include <memory>
#include <variant>
#include <vector>

#include "glint/geometry/surface_point.h"
#include "glint/math/color.h"
#include "glint/shading/image_texture.h"
#include "glint/shading/noise_texture.h"
#include "glint/shading/pattern_texture.h"
#include "glint/shading/projected_image.h"

namespace glint {

enum class CheckerSpace { uv, solid };

struct CheckerTexture {
    Color even{1, 1, 1};
    Color odd{0, 0, 0};
    float size = 1;  // edge of one square: uv units for uv, scene units for solid; > 0
    CheckerSpace space = CheckerSpace::solid;
};

// A pattern or a projected image is held by pointer: its transform would double the size of
// every material.
using PatternTexturePtr = std::shared_ptr<const PatternTexture>;
using ProjectedImagePtr = std::shared_ptr<const ProjectedImage>;
struct PigmentMap;
using PigmentMapPtr = std::shared_ptr<const PigmentMap>;
struct LayeredTexture;
using LayeredTexturePtr = std::shared_ptr<const LayeredTexture>;

using Texture = std::variant<Color, CheckerTexture, ImageTexture, NoiseTexture, PatternTexturePtr,
                             ProjectedImagePtr, PigmentMapPtr, LayeredTexturePtr>;

// A pattern choosing between colour sources, as POV-Ray's pigment_map: the two entries either
// side of the pattern's value blended as a colour map's colours are. Or, as POV-Ray's
// `average`, every entry's colour weighted by its value. Each entry's own pattern is placed by
// its own transform, which includes the map's.
struct PigmentMap {
    struct Entry {
        float at = 0;  // the pattern's value, or the weight when averaged
        Texture texture;
    };
    PatternSpec spec;
    std::vector<Entry> entries;  // sorted by `at`, at least one
    bool average = false;
    Transform to_pattern;  // scene space (or uv space) to the pattern's
    // The map and its entries laid over the surface's uv, at (u, v, 0) (POV-Ray's uv_mapping).
    bool uv_mapping = false;
};

Color evaluate(const PigmentMap& map, const SurfacePoint& sp);

// Colour sources stacked as POV-Ray's layered textures, seen from the top. A layer of colour C,
// filter f and transmit t covers what lies below by its opacity a = 1 - f - t and lets through
// P = f C + t (channel by channel), so that the surface's colour is
//   sum over layers i of (P of the layers above i) a_i w_i C_i
// (an opaque layer ends the sum), w_i the layer's diffuse coefficient relative to the
// material's; and the ambient term's colour likewise with the layer's ambient coefficient.
// Filter and transmit may vary over the surface as the colour does: a second colour source
// gives them, filter in its red channel and transmit in its green.
struct LayeredTexture {
    struct Layer {
        Texture color;
        Texture filter_transmit;
        float diffuse = 1, ambient = 1;  // the layer's kd and ka, relative to its material's
    };
    std::vector<Layer> layers;  // top first, at least one
    // POV-Ray 3.6's opacity, 1 - (f max(C) + t), which scenes written for it were made with.
    bool legacy_opacity = false;
};

// The colours the diffuse and the ambient terms see.
struct LayeredColors {
    Color diffuse, ambient;
};
LayeredColors evaluate_layers(const LayeredTexture& layered, const SurfacePoint& sp);
inline Color evaluate(const LayeredTexture& layered, const SurfacePoint& sp) {
    return evaluate_layers(layered, sp).diffuse;
}

// evaluate() for the kinds other than a constant colour.
Color evaluate_pattern(const Texture& texture, const SurfacePoint& sp);

// The texture's colour at sp. A constant colour, the most common, skips the dispatch: this is
// asked at every hit.
inline Color evaluate(const Texture& texture, const SurfacePoint& sp) {
    if (const auto* color = std::get_if<Color>(&texture)) return *color;
    return evaluate_pattern(texture, sp);
}

// Whether evaluate() reads the surface point's uv: a checker on the surface or an image, at any
// depth of pigment maps and layers.
Uv uv_needed_inside(const Texture& texture);
inline Uv uv_needed(const Texture& texture) {
    if (std::holds_alternative<Color>(texture)) return Uv::skip;
    return uv_needed_inside(texture);
}

}  // namespace glint
