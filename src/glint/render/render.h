// Renders a World into an image: tiles in parallel (oneTBB), samples per pixel from the sampler,
// colours from the scene's integrator, through the reconstruction filter into the film. The image
// is a pure function of the world and the seed, whatever the thread count, tile size or tile
// order.
#pragma once

#include <atomic>
#include <cstdint>

#include "glint/image/image.h"
#include "glint/render/film.h"
#include "glint/render/ray_stats.h"
#include "glint/render/world.h"

namespace glint {

struct RenderOptions {
    int threads = 0;  // 0: all cores
    int tile_size = 16;
    std::uint64_t seed = 0;
    bool record_samples_taken = false;  // fill RenderResult::samples_taken
};

// Shared with a watcher thread (a progress bar) while render() runs.
struct RenderProgress {
    std::atomic<int> tiles_done{0};
    std::atomic<int> tiles_total{0};
    // Set to stop early: tiles not yet started are skipped and stay black.
    std::atomic<bool> cancel{false};
};

struct RenderResult {
    Image image;
    // Samples each pixel took, in every channel: the image of adaptive sampling's work. Empty
    // unless RenderOptions::record_samples_taken.
    Image samples_taken;
    RayStats rays;
    BadSamples bad_samples;
    double seconds = 0;    // wall time
    bool complete = true;  // false when cancelled before every tile was done
};

RenderResult render(const World& world, const RenderOptions& options,
                    RenderProgress* progress = nullptr);

}  // namespace glint
