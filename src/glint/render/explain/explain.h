// `glint explain`: the ray tree of one sample of one pixel, traced by the scene's integrator
// with the render's own code and random numbers, so that it is the sample the render computed.
#pragma once

#include <cstdint>

#include "glint/render/explain/ray_tree.h"
#include "glint/render/world.h"
#include "glint/scene/scene.h"

namespace glint {

struct PixelSample {
    int x = 0, y = 0;  // the pixel, (0, 0) at the top left
    int sample = 0;    // of the pixel's samples_per_pixel
    std::uint64_t seed = 0;
};

// Throws SettingsError (key "pixel" or "sample") when the pixel lies outside the image or the
// sample beyond the pixel's count, and (key "integrator") for an integrator that traces no rays.
void check_explainable(const RenderSettings& settings, const PixelSample& which);

// The tree of that sample, checked first as above.
RayTree explain(const World& world, const PixelSample& which);

}  // namespace glint
