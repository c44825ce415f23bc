// Colour sources for materials: a constant colour, a checker pattern, either painted on the
// surface's uv coordinates (2D) or carved out of space (3D, a solid texture), an image on the
// surface's uv or projected through space, a noise pattern through a colour ramp (solid), one
// of POV-Ray's patterns through a colour map (solid, placed by its own transform), or such a
// pattern choosing between other colour sources (POV-Ray's pigment_map).
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

using Texture = std::variant<Color, CheckerTexture, ImageTexture, NoiseTexture, PatternTexturePtr,
                             ProjectedImagePtr, PigmentMapPtr>;

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
    Transform to_pattern;  // scene space to the pattern's
};

Color evaluate(const PigmentMap& map, const SurfacePoint& sp);

// evaluate() for the kinds other than a constant colour.
Color evaluate_pattern(const Texture& texture, const SurfacePoint& sp);

// The texture's colour at sp. A constant colour, the most common, skips the dispatch: this is
// asked at every hit.
inline Color evaluate(const Texture& texture, const SurfacePoint& sp) {
    if (const auto* color = std::get_if<Color>(&texture)) return *color;
    return evaluate_pattern(texture, sp);
}

// Whether evaluate() reads the surface point's uv: a checker on the surface or an image.
inline Uv uv_needed(const Texture& texture) {
    const auto* checker = std::get_if<CheckerTexture>(&texture);
    return (checker && checker->space == CheckerSpace::uv) ||
                   std::holds_alternative<ImageTexture>(texture)
               ? Uv::compute
               : Uv::skip;
}

}  // namespace glint
