// The render loop: passes of a few samples per pixel, each pass's tiles as oneTBB tasks in an
// arena of the requested size, one integrator per tile, each tile's samples splatted into its own
// part of the film and merged when done, totals merged under a lock, and the stop flags checked
// before each tile and after each pass. The integrator is a template argument, chosen once per
// render: no virtual call per ray.
#include "glint/render/render.h"

#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <map>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>

#include "glint/geometry/traversal_counters.h"
#include "glint/render/eye_sample.h"
#include "glint/render/film/aov_recorder.h"
#include "glint/render/integrators/integrator_family.h"
#include "glint/render/tiles.h"
#include "glint/sampling/sampler.h"

namespace glint {

namespace {

struct TileTotals {
    RayStats rays;
    BadSamples bad;
};

// Sample indices [begin, end) of every pixel.
struct Pass {
    int begin, end;
};

// What every tile of a render reads.
template <class Integrator>
struct RenderInputs {
    const World& world;
    const Sampler& sampler;
    const FilterSampling* filter;  // under adaptive sampling (eye_sample.h); else null
    const typename Integrator::Shared& shared;
    std::mutex& state_mutex;  // held to merge into the state's film and totals
    bool eye_packets;         // RenderOptions::eye_packets
};

// Integrators that shade an eye ray from its nearest hit found beforehand, with the rays of
// neighbouring pixels in one packet.
template <class Integrator>
concept ShadesGivenHits = requires(Integrator& i, const Ray& ray, const std::optional<Hit>& hit,
                                   SampleStream& stream, RayStats& stats) {
    i.trace_eye_ray(ray, hit, nullptr, stream, stats);
};

// A tile's eye rays traced as packets (Wald et al. 2001): blocks of 4 x 2 pixels, one sample
// index at a time, the block's eye rays' nearest hits found together (World::nearest_hits),
// then each ray shaded as alone. Each pixel still takes its samples in order, and the film's
// fixed-point sums do not depend on the order of pixels, so the image is bit for bit that of
// render_tile's loop. Not under adaptive sampling, nor with output variables.
template <class Integrator>
void render_tile_in_packets(const Tile& tile, Pass pass, const RenderInputs<Integrator>& in,
                            RenderState& state, TileTotals& totals) {
    const World& world = in.world;
    const Camera& camera = world.camera();
    const RenderSettings& settings = world.settings();
    const float pencil_scale =
        world.carries_pencils() ? eye_pencil_scale(settings.samples_per_pixel) : 0;
    static_assert(
        !requires(Integrator & i, SampleStream & s, SplatFilm & f, RayStats & r) {
            i.trace_particle(s, f, r);
        },
        "the particles each sample sends are render_tile's");
    Integrator integrator(world, in.shared);  // one per tile: it holds per-thread caches
    FilmTile film_tile = state.film.make_tile(tile);
    constexpr int kBlockWidth = 4, kBlockHeight = kRayPacketSize / kBlockWidth;
    struct Lane {
        int x, y;
        std::optional<PixelPatterns> patterns;
        std::optional<SampleStream> stream;
        EyeSample eye;
        std::size_t ray;  // its index in the packet; kNone when the camera does not see its film
    };
    constexpr std::size_t kNone = kRayPacketSize;
    std::array<Lane, kRayPacketSize> lanes;
    std::array<Ray, kRayPacketSize> rays;
    std::array<std::optional<Hit>, kRayPacketSize> hits;
    for (int y0 = tile.y0; y0 < tile.y1; y0 += kBlockHeight)
        for (int x0 = tile.x0; x0 < tile.x1; x0 += kBlockWidth) {
            std::size_t count = 0;
            for (int y = y0; y < std::min(y0 + kBlockHeight, tile.y1); ++y)
                for (int x = x0; x < std::min(x0 + kBlockWidth, tile.x1); ++x) {
                    const std::size_t pixel =
                        std::size_t(y) * std::size_t(settings.width) + std::size_t(x);
                    Lane& lane = lanes[count++];
                    lane.x = x;
                    lane.y = y;
                    lane.patterns.emplace(in.sampler, pixel);
                    state.samples[pixel] = std::uint32_t(pass.end);
                }
            for (int s = pass.begin; s < pass.end; ++s) {
                // The eye rays in phases, each over all lanes (see EyeNumbers).
                std::array<EyeNumbers, kRayPacketSize> numbers;
                for (std::size_t i = 0; i < count; ++i) {
                    lanes[i].stream.emplace(*lanes[i].patterns, std::uint32_t(s));
                    numbers[i] = eye_numbers(camera, *lanes[i].stream);
                }
                for (std::size_t i = 0; i < count; ++i) find_aperture_point(camera, numbers[i]);
                for (std::size_t i = 0; i < count; ++i)
                    lanes[i].eye = eye_sample(camera, numbers[i], lanes[i].x, lanes[i].y, nullptr,
                                              pencil_scale);
                // Apart from the loop above: a ray read back just after it was written stalls.
                std::size_t traced = 0;
                for (std::size_t i = 0; i < count; ++i) {
                    Lane& lane = lanes[i];
                    lane.ray = kNone;
                    if (camera.sees(lane.eye.film)) {
                        lane.ray = traced;
                        rays[traced++] = lane.eye.ray;
                    }
                }
                world.nearest_hits({rays.data(), traced}, hits.data());
                for (std::size_t i = 0; i < count; ++i) {
                    Lane& lane = lanes[i];
                    const Color c = lane.ray == kNone
                                        ? Color{0, 0, 0}
                                        : integrator.trace_eye_ray(lane.eye.ray, hits[lane.ray],
                                                                   lane.eye.pencil_or_null(),
                                                                   *lane.stream, totals.rays);
                    if (is_valid_sample(c))
                        film_tile.add_sample(lane.eye.film, c);
                    else
                        totals.bad.add({lane.x, lane.y, s});
                }
            }
        }
    const std::lock_guard lock(in.state_mutex);
    state.film.merge(film_tile);
}

// Compiled twice: with the output variables' code (kAovs) and without, the render's own loop.
template <class Integrator, bool kAovs>
void render_tile(const Tile& tile, Pass pass, const RenderInputs<Integrator>& in,
                 RenderState& state, TileTotals& totals) {
    const World& world = in.world;
    // An integrator that draws whole tiles (beam tracing) draws each once, in the first pass;
    // its pixels count every sample as taken.
    if constexpr (requires(Integrator & i, FilmTile & f, RayStats & r) {
                      i.draw_tile(tile, f, r);
                  }) {
        if (pass.begin == 0) {
            Integrator integrator(world, in.shared);
            FilmTile film_tile = state.film.make_tile(tile);
            integrator.draw_tile(tile, film_tile, totals.rays);
            const std::lock_guard lock(in.state_mutex);
            state.film.merge(film_tile);
        }
        for (int y = tile.y0; y < tile.y1; ++y)
            for (int x = tile.x0; x < tile.x1; ++x)
                state.samples[std::size_t(y) * std::size_t(world.settings().width) +
                              std::size_t(x)] = std::uint32_t(pass.end);
        return;
    }
    if constexpr (!kAovs && ShadesGivenHits<Integrator>) {
        if (in.eye_packets && !world.settings().adaptive)
            return render_tile_in_packets(tile, pass, in, state, totals);
    }
    const FilterSampling* filter = in.filter;
    const Camera& camera = world.camera();
    const RenderSettings& settings = world.settings();
    const int width = settings.width;
    const float pencil_scale =
        world.carries_pencils() ? eye_pencil_scale(settings.samples_per_pixel) : 0;
    Integrator integrator(world, in.shared);  // one per tile: it holds per-thread caches
    FilmTile film_tile = state.film.make_tile(tile);
    // Output variables come from a recorder on the integrator, which then runs its recording
    // code; without them the integrator runs the renderer's own.
    AovRecorder recorder(world, state.aovs.set());
    std::optional<AovTile> aov_tile;
    if constexpr (kAovs) {
        integrator.record_into(&recorder);
        aov_tile = state.aovs.make_tile(tile);
    }
    for (int y = tile.y0; y < tile.y1; ++y)
        for (int x = tile.x0; x < tile.x1; ++x) {
            const std::size_t pixel = std::size_t(y) * std::size_t(width) + std::size_t(x);
            std::uint32_t& taken = state.samples[pixel];
            if (int(taken) < pass.begin) continue;  // stopped by adaptive sampling
            PixelError unused;
            PixelError& error = settings.adaptive ? state.errors[pixel] : unused;
            PixelPatterns patterns(in.sampler, pixel);
            int s = pass.begin;
            for (; s < pass.end; ++s) {
                // Adaptive sampling stops a pixel once its error is small enough; its samples
                // are the first of its pattern, so the decision depends on nothing else.
                if (settings.adaptive && s >= settings.adaptive->min_samples &&
                    error.relative_error() < settings.adaptive->threshold)
                    break;
                SampleStream stream(patterns, std::uint32_t(s));
                const EyeSample eye = eye_sample(camera, stream, x, y, filter, pencil_scale);
                TraversalCounters before;
                if constexpr (kAovs) {
                    recorder.start();
                    before = traversal_counters;
                }
                const Color c = camera.sees(eye.film)
                                    ? integrator.trace_eye_ray(eye.ray, eye.pencil_or_null(),
                                                               stream, totals.rays)
                                    : Color{0, 0, 0};
                if (is_valid_sample(c)) {
                    if (filter)
                        film_tile.add_to_pixel(x, y, eye.weight, c);
                    else
                        film_tile.add_sample(eye.film, c);
                    if (settings.adaptive) error.add(c);
                    if constexpr (kAovs) {
                        AovSample a = recorder.sample();
                        a.nodes = traversal_counters.nodes - before.nodes;
                        a.primitives = traversal_counters.primitives - before.primitives;
                        aov_tile->add(eye.film, x, y, s, eye.weight, a);
                    }
                } else {
                    totals.bad.add({x, y, s});
                }
                // The integrators that trace light forwards send a particle with each sample.
                if constexpr (requires {
                                  integrator.trace_particle(stream, *state.splats, totals.rays);
                              })
                    integrator.trace_particle(stream, *state.splats, totals.rays);
            }
            taken = std::uint32_t(s);
        }
    const std::lock_guard lock(in.state_mutex);
    state.film.merge(film_tile);
    if constexpr (kAovs) state.aovs.merge(*aov_tile);
}

// Checks a work list against the state (render() says what it takes) and puts it in the order it
// is rendered: by pass, then by tile.
std::vector<WorkPiece> ordered_work(std::span<const WorkPiece> work, const RenderState& state,
                                    int passes) {
    std::vector<WorkPiece> ordered(work.begin(), work.end());
    std::sort(ordered.begin(), ordered.end(), [](const WorkPiece& a, const WorkPiece& b) {
        return a.pass != b.pass ? a.pass < b.pass : a.tile < b.tile;
    });
    const int tiles = int(state.tile_passes.size());
    // Each listed tile's next pass, as the list goes. Only the listed tiles' entries are read:
    // others may be written meanwhile (the pieces a cluster's rank 0 takes back from others).
    std::map<int, int> next;
    for (const WorkPiece& piece : ordered) {
        if (piece.tile < 0 || piece.tile >= tiles || piece.pass < 0 || piece.pass >= passes)
            throw std::invalid_argument("render: piece (pass " + std::to_string(piece.pass) +
                                        ", tile " + std::to_string(piece.tile) +
                                        ") is outside the render's " + std::to_string(passes) +
                                        " passes of " + std::to_string(tiles) + " tiles");
        int& at =
            next.try_emplace(piece.tile, state.tile_passes[std::size_t(piece.tile)]).first->second;
        if (piece.pass != at)
            throw std::invalid_argument("render: tile " + std::to_string(piece.tile) +
                                        " is at pass " + std::to_string(at) + ", not " +
                                        std::to_string(piece.pass) +
                                        ": each tile's passes come one after another, once");
        ++at;
    }
    return ordered;
}

// Renders the pieces of `work` (ordered_work's order), pass by pass, until the last or a stop.
// Returns whether every piece was done.
template <class Integrator>
bool render_work(const World& world, const RenderOptions& options, const std::vector<Tile>& tiles,
                 std::span<const WorkPiece> work, RenderProgress* progress, RenderState& state) {
    const RenderSettings& settings = world.settings();
    const int spp = settings.samples_per_pixel;
    const int size = state.pass_size;
    const Sampler sampler(sampler_of(settings), spp, options.seed);
    std::optional<FilterSampling> filter_sampling;
    if (importance_samples_filter(settings)) filter_sampling.emplace(filter_of(settings));
    // An explicit thread count may exceed the cores (to check determinism, say): lift TBB's
    // default cap on workers for the duration of the render.
    std::optional<tbb::global_control> allow_threads;
    if (options.threads > 0)
        allow_threads.emplace(tbb::global_control::max_allowed_parallelism, options.threads);
    tbb::task_arena arena(options.threads > 0 ? options.threads : tbb::task_arena::automatic);
    // In the arena: what an integrator prepares in parallel (beam tracing's shadow polygons)
    // keeps to the render's threads.
    using Shared = typename Integrator::Shared;
    IntegratorCache own_cache;
    IntegratorCache& cache = options.integrator_cache ? *options.integrator_cache : own_cache;
    if (!cache.shared)
        cache.shared =
            std::make_shared<Shared>(arena.execute([&] { return Integrator::prepare(world); }));
    Shared& shared = *static_cast<Shared*>(cache.shared.get());
    std::mutex own_mutex;
    std::mutex& state_mutex = options.state_mutex ? *options.state_mutex : own_mutex;
    const RenderInputs<Integrator> inputs{
        world,  sampler,     filter_sampling ? &*filter_sampling : nullptr,
        shared, state_mutex, options.eye_packets};
    std::atomic<int> tiles_finished{0};
    for (std::size_t first = 0; first < work.size();) {
        // This pass's pieces: work[first, last).
        const int pass_index = work[first].pass;
        std::size_t last = first;
        while (last < work.size() && work[last].pass == pass_index) ++last;
        const Pass pass{pass_index * size, std::min(spp, (pass_index + 1) * size)};
        std::atomic<bool> skipped{false};
        // The rays the pass's preparation traced (photon maps): counted once, with tile 0's
        // piece of the pass, though a pass continued after a stop, or rendered in parts on
        // several machines, prepares again.
        arena.execute([&] {
            if constexpr (requires(RayStats & r) {
                              Integrator::begin_pass(shared, world, 0, std::uint64_t(0), r);
                          }) {
                if (cache.pass != pass_index) {
                    cache.pass_rays = RayStats{};
                    Integrator::begin_pass(shared, world, pass.begin, options.seed,
                                           cache.pass_rays);
                    cache.pass = pass_index;
                }
            }
            // One tile per task: tiles are large enough to amortise scheduling.
            tbb::parallel_for(
                tbb::blocked_range<std::size_t>(first, last, 1),
                [&](const tbb::blocked_range<std::size_t>& range) {
                    for (std::size_t i = range.begin(); i != range.end(); ++i) {
                        const int tile = work[i].tile;
                        if (progress && progress->cancel) {
                            skipped = true;
                            continue;
                        }
                        TileTotals totals;
                        if (state.aovs.empty())
                            render_tile<Integrator, false>(tiles[std::size_t(tile)], pass, inputs,
                                                           state, totals);
                        else
                            render_tile<Integrator, true>(tiles[std::size_t(tile)], pass, inputs,
                                                          state, totals);
                        if (tile == 0) totals.rays += cache.pass_rays;
                        {
                            const std::lock_guard lock(state_mutex);
                            state.rays += totals.rays;
                            state.bad_samples += totals.bad;
                        }
                        // Tasks write distinct elements.
                        state.tile_passes[std::size_t(tile)] = pass_index + 1;
                        if (progress) ++progress->tiles_done;
                        if (options.after_tile) options.after_tile(++tiles_finished);
                        if (options.after_piece) options.after_piece(pass_index, tile);
                    }
                },
                tbb::simple_partitioner());
        });
        if (skipped) return false;
        first = last;
        if (progress) progress->passes_done = state.passes_done();
        if (first == work.size()) break;
        if (progress && (progress->stop_after_pass || progress->cancel)) return false;
        if (options.after_pass && state.passes_done() == pass_index + 1) {
            options.after_pass(state);
            // A stop asked for while it ran (a slow checkpoint) need not wait for another pass.
            if (progress && (progress->stop_after_pass || progress->cancel)) return false;
        }
    }
    return true;
}

// The samples each pixel took, in every channel.
Image samples_image(const RenderState& state) {
    Image image(state.width, state.height);
    for (std::size_t i = 0; i < state.samples.size(); ++i)
        image.pixels[i] = Color::gray(float(state.samples[i]));
    return image;
}

}  // namespace

int pass_size_of(const RenderSettings& settings, const RenderOptions& options) {
    if (const int fixed = integrator_info(settings.integrator).pass_size; fixed > 0) return fixed;
    return options.pass_size > 0 ? options.pass_size : samples_per_pass(settings.samples_per_pixel);
}

std::vector<WorkPiece> remaining_work(const RenderState& state, int passes) {
    std::vector<WorkPiece> work;
    for (int pass = state.passes_done(); pass < passes; ++pass)
        for (std::size_t tile = 0; tile < state.tile_passes.size(); ++tile)
            if (state.tile_passes[tile] <= pass) work.push_back({pass, int(tile)});
    return work;
}

RenderState initial_state(const RenderSettings& settings, const RenderOptions& options) {
    return RenderState(settings, options.tile_size, pass_size_of(settings, options), options.aovs);
}

Image resolve_image(const RenderState& state) {
    Image image = state.film.resolve();
    if (state.splats && state.rays.particles > 0) {
        // Each particle stands for the whole film: over the particles per pixel.
        const Image particles = state.splats->resolve(
            float(double(state.width) * double(state.height) / double(state.rays.particles)));
        for (std::size_t i = 0; i < image.pixels.size(); ++i)
            image.pixels[i] += particles.pixels[i];
    }
    // The film holds the working space's values; the image is the linear light they stand for.
    for (Color& c : image.pixels) c = decode(state.working_space, c);
    return image;
}

bool render_pieces(const World& world, const RenderOptions& options, RenderState& state,
                   std::span<const WorkPiece> work, RenderProgress* progress) {
    const auto start = std::chrono::steady_clock::now();
    const RenderSettings& settings = world.settings();
    const std::vector<Tile> tiles = make_tiles(settings.width, settings.height, options.tile_size);
    if (state.width != settings.width || state.height != settings.height ||
        state.tile_passes.size() != tiles.size() ||
        state.pass_size != pass_size_of(settings, options) || state.aovs.set() != options.aovs)
        throw std::invalid_argument(
            "render: the state is of another image, tile or pass size, or other output variables");
    const int passes = pass_count(settings.samples_per_pixel, state.pass_size);
    const std::vector<WorkPiece> pieces =
        work.empty() ? remaining_work(state, passes) : ordered_work(work, state, passes);
    if (progress) {
        int done = 0;
        if (work.empty())  // the whole render: what earlier calls did counts too
            for (const int tile : state.tile_passes) done += tile;
        // Done before total: a watcher that sees the total sees the count it starts from.
        progress->tiles_done = done;
        progress->passes_done = state.passes_done();
        progress->passes_total = passes;
        progress->tiles_total = done + int(pieces.size());
    }
    const bool complete = with_integrator(settings.integrator, [&]<class Integrator>() {
        return render_work<Integrator>(world, options, tiles, pieces, progress, state);
    });
    state.seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return complete;
}

RenderResult render_result(const RenderState& state, const RenderOptions& options) {
    RenderResult result;
    result.image = resolve_image(state);
    if (options.record_samples_taken) result.samples_taken = samples_image(state);
    result.aovs = state.aovs.resolve();
    if (options.aovs.has(Aov::samples)) {
        // In Aov order: before the traversal counts, the only variables after it.
        auto at = result.aovs.begin();
        while (at != result.aovs.end() && at->aov < Aov::samples) ++at;
        result.aovs.insert(at, {Aov::samples, samples_image(state)});
    }
    result.rays = state.rays;
    result.bad_samples = state.bad_samples;
    result.seconds = state.seconds;
    return result;
}

RenderResult render(const World& world, const RenderOptions& options, RenderProgress* progress,
                    RenderState* state, std::span<const WorkPiece> work) {
    std::optional<RenderState> fresh;
    if (!state) state = &fresh.emplace(initial_state(world.settings(), options));
    const bool complete = render_pieces(world, options, *state, work, progress);
    RenderResult result = render_result(*state, options);
    result.complete = complete;
    return result;
}

}  // namespace glint
