// POV-Ray's sky_sphere onto glint's sky: an equirectangular image baked from its pigments.
#pragma once

#include <functional>

#include "glint/scene/pov/pov_items.h"
#include "glint/shading/sky.h"

namespace glint {

// The sky image of `sky`, `width` by width / 2 pixels. In each direction its pigments are
// layered from the first up, each letting what lies below through by its filter and transmit,
// with `background` below them all; `encode_image` turns an image pigment's linear light into
// the scene's working space (RenderSettings::working_space), which the rest is in as written.
SkyImage bake_sky(const PovSkySphere& sky, Color background,
                  const std::function<Color(Color)>& encode_image, int width = 1024);

}  // namespace glint
