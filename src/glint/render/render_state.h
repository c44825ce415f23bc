// Everything a render needs to continue where it stopped: the film's sums, each pixel's samples
// and adaptive error, the totals so far, and how far the passes got. A render continued from a
// saved state gives the image, ray counts and samples of an uninterrupted one, bit for bit.
#pragma once

#include <algorithm>
#include <cstdint>
#include <optional>
#include <vector>

#include "glint/render/film/aov_films.h"
#include "glint/render/film/film.h"
#include "glint/render/film/pixel_error.h"
#include "glint/render/film/splat_film.h"
#include "glint/render/ray_stats.h"
#include "glint/scene/scene.h"

namespace glint {

// Samples of every pixel in one pass: a sixteenth of the render, so that a stop after the pass in
// flight comes soon, but at least 16 (or all there are): each pass works out every pixel's pattern
// keys again, which cost a 64-spp render 7% in passes of 4 samples and 4% in passes of 8
// (bench/README.md).
inline int samples_per_pass(int samples_per_pixel) {
    return std::max((samples_per_pixel + 15) / 16, std::min(samples_per_pixel, 16));
}
inline int pass_count(int samples_per_pixel, int pass_size) {
    return (samples_per_pixel + pass_size - 1) / pass_size;
}

struct RenderState {
    // A render not yet started, of settings' image in tiles of tile_size, pass_size samples per
    // pixel a pass, with films for the output variables `aovs`.
    RenderState(const RenderSettings& settings, int tile_size, int pass_size, AovSet aovs = {});

    int width, height;
    int pass_size;
    WorkingSpace working_space;  // what resolve_image() decodes the film's values from
    Film film;
    // The particles' film, for the integrators that trace particles from the lights.
    std::optional<SplatFilm> splats;
    AovFilms aovs;  // none unless asked for; a resume file does not hold them
    // Samples each pixel has taken, row by row. Under adaptive sampling a pixel that took fewer
    // than the passes before offered has stopped.
    std::vector<std::uint32_t> samples;
    std::vector<PixelError> errors;  // each pixel's, under adaptive sampling only
    RayStats rays;
    BadSamples bad_samples;
    double seconds = 0;  // wall time of the render so far
    // The passes each tile (make_tiles order) has done. Tiles are independent, so a render may
    // take them in any order as long as each tile's passes come one after another: a render
    // stopped between tiles continues with the others, and a work list may run one tile
    // through all its passes before the next.
    std::vector<int> tile_passes;

    // The passes every tile has done: the pass in flight, or the pass count when all are done.
    int passes_done() const {
        return tile_passes.empty() ? 0 : *std::min_element(tile_passes.begin(), tile_passes.end());
    }
};

}  // namespace glint
