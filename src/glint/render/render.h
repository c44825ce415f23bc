// Renders a World into an image: in passes of a few samples per pixel each, tiles in parallel
// (oneTBB), colours from the scene's integrator, through the reconstruction filter into the film.
// The image is a pure function of the world and the seed, whatever the thread count, tile size,
// tile order, or where a render was stopped and continued.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <span>
#include <vector>

#include "glint/image/image.h"
#include "glint/render/film/aov_films.h"
#include "glint/render/film/film.h"
#include "glint/render/ray_stats.h"
#include "glint/render/render_state.h"
#include "glint/render/world.h"

namespace glint {

// A piece of a render's work: one tile (its index in make_tiles order) through one pass.
struct WorkPiece {
    int pass = 0;
    int tile = 0;
    bool operator==(const WorkPiece&) const = default;
};

// What an integrator prepares for a render (beam tracing's shadow polygons) and for the pass in
// flight (a photon map), kept between the calls of render_pieces a front end makes for pieces of
// one render and options (a rank of a cluster, asked for a few tiles at a time): built once, and
// once a pass, as one call builds them.
struct IntegratorCache {
    std::shared_ptr<void> shared;  // the integrator's Shared
    int pass = -1;                 // the pass its begin_pass prepared; -1: none
    RayStats pass_rays;            // the rays that preparation traced
};

struct RenderOptions {
    int threads = 0;  // 0: all cores
    int tile_size = 16;
    std::uint64_t seed = 0;
    bool record_samples_taken = false;  // fill RenderResult::samples_taken
    AovSet aovs;                        // output variables to fill RenderResult::aovs with
    int pass_size = 0;                  // samples each pixel takes a pass; 0: samples_per_pass
    // Eye rays traced in packets of neighbouring pixels where the integrator can (Whitted's, the
    // distributed ray tracer and the path tracer, without adaptive sampling or output
    // variables); false: one by one. The image is the same bit for bit either way.
    bool eye_packets = true;
    // Called on render()'s thread after each pass but the last, with the state so far (to save a
    // checkpoint, say); the render waits for it.
    std::function<void(const RenderState&)> after_pass;
    // Called on the render thread that finished a tile, with the tiles finished so far in this
    // call of render(), counting each tile once a pass; that thread waits for it. Concurrent.
    std::function<void(int tiles_finished)> after_tile;
    // Likewise, with the piece of work it finished: the pass, and the tile's index in
    // make_tiles order.
    std::function<void(int pass, int tile)> after_piece;
    // Held while a tile's samples are merged into the state's film and totals: holding it, other
    // threads may read those while the render runs (RenderJob::image_so_far). Null: the
    // render's own.
    std::mutex* state_mutex = nullptr;
    // Kept between calls for one world and these options; null: each call prepares its own.
    IntegratorCache* integrator_cache = nullptr;
};

// Shared with a watcher thread (a progress bar) while render() runs.
struct RenderProgress {
    // Tiles rendered, counting each tile once a pass, of tiles x passes.
    std::atomic<int> tiles_done{0};
    std::atomic<int> tiles_total{0};
    std::atomic<int> passes_done{0};
    std::atomic<int> passes_total{0};
    // Set to stop once the pass in flight is done: every pixel then has the same samples.
    std::atomic<bool> stop_after_pass{false};
    // Set to stop now: tiles not yet started are skipped; those in flight finish.
    std::atomic<bool> cancel{false};
};

struct RenderResult {
    Image image;
    // Samples each pixel took, in every channel: the image of adaptive sampling's work. Empty
    // unless RenderOptions::record_samples_taken.
    Image samples_taken;
    // The output variables asked for, in Aov order (`samples` is samples_taken).
    std::vector<AovImage> aovs;
    RayStats rays;
    BadSamples bad_samples;
    double seconds = 0;    // wall time, earlier calls on the same state included
    bool complete = true;  // false when stopped before every piece asked for was done
};

// The samples each pixel takes a pass, and a render's state before its first pass.
int pass_size_of(const RenderSettings& settings, const RenderOptions& options);
RenderState initial_state(const RenderSettings& settings, const RenderOptions& options);

// The image a state holds: its film resolved, and the light integrator's particles' film added.
Image resolve_image(const RenderState& state);

// Every piece left to do in `state`, pass by pass, tiles in make_tiles order within a pass.
std::vector<WorkPiece> remaining_work(const RenderState& state, int passes);

// Renders from `state` (which must be of this world's settings and options' tile and pass sizes,
// as initial_state makes it), or from the start without one, and leaves in it the state
// reached: the pieces of `work`, or without a list every piece left. A list may hold any pieces
// in any order so long as each tile's are the passes that follow those it has done, one after
// another (std::invalid_argument otherwise); they are rendered pass by pass. Progress counts
// the list's pieces. The result's counts are the render's totals, those of earlier calls on the
// state included.
RenderResult render(const World& world, const RenderOptions& options,
                    RenderProgress* progress = nullptr, RenderState* state = nullptr,
                    std::span<const WorkPiece> work = {});

// As render() into `state`, without resolving an image at the end: for a front end that renders
// a few pieces at a time. Returns whether every piece asked for was done.
bool render_pieces(const World& world, const RenderOptions& options, RenderState& state,
                   std::span<const WorkPiece> work, RenderProgress* progress = nullptr);

// What render() returns for the state it reached: the image, the output variables and the counts
// (`complete` left true).
RenderResult render_result(const RenderState& state, const RenderOptions& options);

}  // namespace glint
