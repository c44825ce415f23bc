// The render loop: tiles as oneTBB tasks in an arena of the requested size, one integrator per
// tile, each tile's samples splatted into its own part of the film and merged when done, totals
// merged under a lock, and a cancel flag checked before each tile. The integrator is a template
// argument, chosen once per render: no virtual call per ray.
#include "glint/render/render.h"

#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <mutex>
#include <optional>

#include "glint/render/distributed.h"
#include "glint/render/tiles.h"
#include "glint/render/whitted.h"
#include "glint/sampling/sampler.h"

namespace glint {

namespace {

struct TileTotals {
    RayStats rays;
    BadSamples bad;
};

// A pixel's running mean and variance of luminance (Welford), for adaptive sampling.
class PixelError {
public:
    void add(Color c) {
        const double y = luminance(c);
        ++n_;
        const double delta = y - mean_;
        mean_ += delta / n_;
        m2_ += delta * (y - mean_);
    }
    // 1.96 standard errors of the mean over max(mean, the dark level).
    double relative_error() const {
        if (n_ < 2) return kInfinity;
        const double standard_error = std::sqrt(m2_ / (n_ - 1) / n_);
        return 1.96 * standard_error / std::max(std::abs(mean_), double(kAdaptiveDarkLevel));
    }

private:
    static double luminance(Color c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }
    int n_ = 0;
    double mean_ = 0, m2_ = 0;
};

template <class Integrator>
void render_tile(const Tile& tile, const World& world, const Sampler& sampler, Film& film,
                 Image* samples_taken, TileTotals& totals) {
    const Camera& camera = world.camera();
    const RenderSettings& settings = world.settings();
    const int width = settings.width;
    Integrator integrator(world);  // one per tile: it holds per-thread caches
    FilmTile film_tile = film.make_tile(tile);
    for (int y = tile.y0; y < tile.y1; ++y)
        for (int x = tile.x0; x < tile.x1; ++x) {
            PixelError error;
            PixelPatterns patterns(sampler, std::uint64_t(y) * std::uint64_t(width) + x);
            int s = 0;
            for (; s < sampler.samples_per_pixel(); ++s) {
                // Adaptive sampling stops a pixel once its error is small enough; its samples
                // are the first of its pattern, so the decision depends on nothing else.
                if (settings.adaptive && s >= settings.adaptive->min_samples &&
                    error.relative_error() < settings.adaptive->threshold)
                    break;
                SampleStream stream(patterns, std::uint32_t(s));
                const Point2 offset = stream.get_2d(kPixelDimension);
                const Point2 p{float(x) + offset.x, float(y) + offset.y};
                // A pinhole and a closed shutter draw no numbers for the lens and the time.
                const Point2 lens =
                    camera.has_lens() ? stream.get_2d(kLensDimension) : Point2{0.5f, 0.5f};
                const float time = camera.has_shutter()
                                       ? camera.shutter_time(stream.get_1d(kTimeDimension))
                                       : camera.shutter_open();
                const Color c = integrator.trace_eye_ray(camera.generate_ray(p, lens, time), stream,
                                                         totals.rays);
                if (is_valid_sample(c)) {
                    film_tile.add_sample(p, c);
                    if (settings.adaptive) error.add(c);
                } else {
                    totals.bad.add({x, y, s});
                }
            }
            if (samples_taken) samples_taken->at(x, y) = Color::gray(float(s));
        }
    film.merge(film_tile);
}

template <class Integrator>
void render_tiles(const World& world, const RenderOptions& options, const std::vector<Tile>& tiles,
                  Film& film, RenderProgress* progress, RenderResult& result) {
    const RenderSettings& settings = world.settings();
    const Sampler sampler(sampler_of(settings), settings.samples_per_pixel, options.seed);
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
                    render_tile<Integrator>(
                        tiles[i], world, sampler, film,
                        options.record_samples_taken ? &result.samples_taken : nullptr, totals);
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
    result.complete = !skipped;
}

}  // namespace

RenderResult render(const World& world, const RenderOptions& options, RenderProgress* progress) {
    const auto start = std::chrono::steady_clock::now();
    const RenderSettings& settings = world.settings();
    const std::vector<Tile> tiles = make_tiles(settings.width, settings.height, options.tile_size);
    if (progress) progress->tiles_total = static_cast<int>(tiles.size());

    Film film(settings.width, settings.height, filter_of(settings));
    RenderResult result;
    if (options.record_samples_taken) result.samples_taken = Image(settings.width, settings.height);
    switch (settings.integrator) {
        case IntegratorKind::whitted:
            render_tiles<WhittedIntegrator>(world, options, tiles, film, progress, result);
            break;
        case IntegratorKind::distributed:
            render_tiles<DistributedIntegrator>(world, options, tiles, film, progress, result);
            break;
    }
    result.image = film.resolve();
    result.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

}  // namespace glint
