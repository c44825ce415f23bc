// Colour sources for materials: a constant colour, a checker pattern, either painted on the
// surface's uv coordinates (2D) or carved out of space (3D, a solid texture), an image, or a
// noise pattern through a colour ramp (solid).
#pragma once

#include <variant>

#include "glint/geometry/surface_point.h"
#include "glint/math/color.h"
#include "glint/shading/image_texture.h"
#include "glint/shading/noise_texture.h"

namespace glint {

enum class CheckerSpace { uv, solid };

struct CheckerTexture {
    Color even{1, 1, 1};
    Color odd{0, 0, 0};
    float size = 1;  // edge of one square: uv units for uv, scene units for solid; > 0
    CheckerSpace space = CheckerSpace::solid;
};

using Texture = std::variant<Color, CheckerTexture, ImageTexture, NoiseTexture>;

Color evaluate(const Texture& texture, const SurfacePoint& sp);

}  // namespace glint
