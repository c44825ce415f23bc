// Colour sources for materials: a constant colour, a checker pattern, either painted on the
// surface's uv coordinates (2D) or carved out of space (3D, a solid texture), an image on the
// surface's uv or projected through space, a noise pattern through a colour ramp (solid), or one
// of POV-Ray's patterns through a colour map (solid, placed by its own transform).
#pragma once

#include <memory>
#include <variant>

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

using Texture = std::variant<Color, CheckerTexture, ImageTexture, NoiseTexture, PatternTexturePtr,
                             ProjectedImagePtr>;

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
