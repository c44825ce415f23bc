// `glint explain`: the ray tree of one sample of one pixel, traced by the scene's integrator
// with the render's own code and random numbers, so that it is the sample the render computed.
#pragma once

#include <cstdint>

#include "glint/render/explain/ray_tree.h"
#include "glint/render/world.h"

namespace glint {

struct PixelSample {
    int x = 0, y = 0;  // the pixel, (0, 0) at the top left
    int sample = 0;    // of the pixel's samples_per_pixel
    std::uint64_t seed = 0;
};

// The tree of that sample; x, y and sample must lie within the world's image and sample count.
RayTree explain(const World& world, const PixelSample& which);

}  // namespace glint
