// What `glint render` and `glint merge` print when they have written an image.
#pragma once

#include <string>

#include "glint/render/render.h"

namespace glint::cli {

// "glint: wrote OUTPUT (NOTE; 640x480, 16 spp) in 2.31 s", then the rays of each kind.
void print_summary(const std::string& output, const RenderSettings& s, const RenderResult& r,
                   const std::string& note = {});

}  // namespace glint::cli
