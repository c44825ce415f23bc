// The render loop: tiles as oneTBB tasks in an arena of the requested size, one integrator per
// tile, totals merged under a lock, and a cancel flag checked before each tile.
#include "glint/render/render.h"

#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <chrono>
#include <mutex>
#include <optional>

#include "glint/render/tiles.h"
#include "glint/render/whitted.h"
#include "glint/sampling/pixel_sampler.h"

namespace glint {

namespace {

struct TileTotals {
    RayStats rays;
    BadSamples bad;
};

void render_tile(const Tile& tile, const World& world, const PixelSampler& sampler, Film& film,
                 TileTotals& totals) {
    const Camera& camera = world.camera();
    WhittedIntegrator integrator(world);  // one per tile: it holds per-thread caches
    for (int y = tile.y0; y < tile.y1; ++y)
        for (int x = tile.x0; x < tile.x1; ++x)
            for (int s = 0; s < sampler.samples_per_pixel(); ++s) {
                const Point2 offset = sampler.offset(s);
                const Ray ray = camera.generate_ray({float(x) + offset.x, float(y) + offset.y});
                film.add_sample({x, y, s}, integrator.trace_eye_ray(ray, totals.rays), totals.bad);
            }
}

}  // namespace

RenderResult render(const World& world, const RenderOptions& options, RenderProgress* progress) {
    const auto start = std::chrono::steady_clock::now();
    const RenderSettings& settings = world.settings();
    const std::vector<Tile> tiles = make_tiles(settings.width, settings.height, options.tile_size);
    if (progress) progress->tiles_total = static_cast<int>(tiles.size());

    Film film(settings.width, settings.height);
    const PixelSampler sampler(settings.sampler, settings.samples_per_pixel, options.seed);

    RenderResult result;
    std::mutex totals_mutex;
    std::atomic<bool> skipped{false};
    // An explicit thread count may exceed the cores (to check determinism, say): lift TBB's
    // default cap on workers for the duration of the render.
    std::optional<tbb::global_control> allow_threads;
    if (options.threads > 0)
        allow_threads.emplace(tbb::global_control::max_allowed_parallelism, options.threads);
    tbb::task_arena arena(options.threads > 0 ? options.threads : tbb::task_arena::automatic);
    arena.execute([&] {
        // One tile per task: tiles are large enough to amortise scheduling.
        tbb::parallel_for(
            tbb::blocked_range<std::size_t>(0, tiles.size(), 1),
            [&](const tbb::blocked_range<std::size_t>& range) {
                for (std::size_t i = range.begin(); i != range.end(); ++i) {
                    if (progress && progress->cancel) {
                        skipped = true;
                        continue;
                    }
                    TileTotals totals;
                    render_tile(tiles[i], world, sampler, film, totals);
                    {
                        const std::lock_guard lock(totals_mutex);
                        result.rays += totals.rays;
                        result.bad_samples += totals.bad;
                    }
                    if (progress) ++progress->tiles_done;
                }
            },
            tbb::simple_partitioner());
    });

    result.image = film.resolve();
    result.complete = !skipped;
    result.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

}  // namespace glint
