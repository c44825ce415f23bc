// What a scene file may ask for, checked as the file is read, before memory or time is taken for
// it, so that an absurd or hostile scene is an error, not an outage. The defaults are
// SceneLimits'; the command line raises them (--max-pixels, --max-samples, --max-ray-depth) up to
// the ceilings, what glint's structures hold. What the command line itself asks (--width, --spp,
// --max-depth) is bounded by the ceilings alone. docs/cli.md lists them all.
#pragma once

#include <cstdint>

#include "glint/image/image_limits.h"  // kMaxImagePixels, kMaxWrittenImagePixels

namespace glint {

// The ceilings.
inline constexpr int kMaxImageSide = 65536;
inline constexpr std::int64_t kMaxRenderPixels = kMaxWrittenImagePixels;  // 65536 x 65536
// The one-pixel box film counts a pixel's samples in a float, exact up to 2^24.
inline constexpr int kMaxSamplesPerPixel = 1 << 24;
// Each level of the ray tree is a level of recursion on a worker thread's stack.
inline constexpr int kMaxDepth = 1024;
inline constexpr int kMaxShadowRays = 4096;
// Photons a pass: each takes 48 bytes while its pass's map stands.
inline constexpr int kMaxPhotonsPerPass = 1 << 24;
// A shadow map's texels along a face's edge: six faces of 4096^2 floats are 400 MB a light.
inline constexpr int kMaxShadowMapResolution = 4096;
// An animation's frames: a frame number fills out.########.png's eight digits.
inline constexpr int kMaxFrames = 99999999;

struct SceneLimits {
    std::int64_t image_pixels = kMaxImagePixels;  // of the render, and of every image read
    int samples_per_pixel = 65536;
    int max_depth = 64;
    // Times a scene's script loops may run (POV-Ray's #while and #for, all together): an
    // endless loop stops with an error within seconds.
    std::int64_t script_loop_iterations = 1'000'000;
};

}  // namespace glint
