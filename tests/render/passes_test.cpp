// Rendering in passes: the image, ray counts and samples taken are the same bit for bit however
// the samples are split into passes, and when a render is stopped (after a pass, or between
// tiles) and continued from its state.
#include <gtest/gtest.h>

#include <cstring>
#include <thread>

#include "common/under_sanitizer.h"
#include "glint/render/render.h"
#include "glint/scene/yaml/yaml_scene_loader.h"

namespace glint {
namespace {

struct Case {
    const char* name;
    Scene scene;
};

Scene load(const char* file, int width, int height) {
    Scene scene = load_yaml_scene(std::string(GLINT_SOURCE_DIR) + file);
    scene.settings.width = width;
    scene.settings.height = height;
    return scene;
}

// Whitted's film (the one-pixel box over a regular grid), the box under jittered samples, a
// Gaussian reaching across tiles, and distributed ray tracing with adaptive sampling.
std::vector<Case> cases() {
    std::vector<Case> all;
    Scene whitted = load("/scenes/showcase.yaml", 40, 30);
    whitted.settings.samples_per_pixel = 4;
    all.push_back({"whitted", whitted});
    Scene box = load("/scenes/showcase.yaml", 40, 30);
    box.settings.sampler = SamplerKind::jittered;
    box.settings.samples_per_pixel = 7;
    box.settings.filter = FilterSpec{};
    all.push_back({"box", box});
    Scene gaussian = box;
    gaussian.settings.filter = FilterSpec{FilterKind::gaussian, 1.5f};
    all.push_back({"gaussian", gaussian});
    Scene adaptive = load("/scenes/distributed-showcase.yaml", 40, 24);
    adaptive.settings.samples_per_pixel = 24;
    adaptive.settings.adaptive = AdaptiveSampling{0.05f, 4};
    all.push_back({"distributed adaptive", adaptive});
    return all;
}

bool same_pixels(const Image& a, const Image& b) {
    return a.width == b.width && a.height == b.height &&
           std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(Color)) == 0;
}

void expect_same_render(const RenderResult& r, const RenderResult& reference,
                        const std::string& what) {
    EXPECT_TRUE(r.complete) << what;
    EXPECT_TRUE(same_pixels(r.image, reference.image)) << what;
    EXPECT_TRUE(same_pixels(r.samples_taken, reference.samples_taken)) << what;
    EXPECT_EQ(r.rays, reference.rays) << what;
    EXPECT_EQ(r.bad_samples.count, reference.bad_samples.count) << what;
}

RenderOptions options_of(int threads, int pass_size) {
    RenderOptions options;
    options.threads = threads;
    options.tile_size = 8;
    options.seed = 5;
    options.record_samples_taken = true;
    options.pass_size = pass_size;
    return options;
}

TEST(Passes, ImageIsIdenticalForAnySplitIntoPassesAndAnyThreadCount) {
    for (const Case& c : cases()) {
        const World world(c.scene);
        const int spp = c.scene.settings.samples_per_pixel;
        const RenderResult one_pass = render(world, options_of(1, spp));
        ASSERT_TRUE(one_pass.complete);
        for (const auto& [threads, pass_size] :
             {std::pair{1, 1}, std::pair{2, 2}, std::pair{3, 3}, std::pair{4, 0}}) {
            expect_same_render(render(world, options_of(threads, pass_size)), one_pass,
                               std::string(c.name) + ", " + std::to_string(threads) +
                                   " threads, passes of " + std::to_string(pass_size));
        }
    }
}

TEST(Passes, RenderStoppedAfterEachPassAndContinuedIsIdentical) {
    for (const Case& c : cases()) {
        const World world(c.scene);
        const RenderOptions options = options_of(2, 2);
        const RenderResult reference = render(world, options);
        RenderState state = initial_state(c.scene.settings, options);
        RenderProgress progress;
        progress.stop_after_pass = true;
        RenderResult r;
        int stops = 0;
        do {
            r = render(world, options, &progress, &state);
            stops += !r.complete;
            ASSERT_LT(stops, 100) << c.name;
        } while (!r.complete);
        EXPECT_EQ(stops, (c.scene.settings.samples_per_pixel + 1) / 2 - 1) << c.name;
        expect_same_render(r, reference, c.name);
    }
}

TEST(Passes, RenderStoppedBetweenTilesAndContinuedIsIdentical) {
    int mid_pass = 0;
    for (Case& c : cases()) {
        // Larger, in small tiles: the stops, timed by another thread, fall within passes. Twice
        // as large under a sanitizer, where each of the many restarts costs more.
        const int scale = testing::kUnderSanitizer ? 2 : 3;
        c.scene.settings.width *= scale;
        c.scene.settings.height *= scale;
        const World world(c.scene);
        RenderOptions options = options_of(1, 3);
        options.tile_size = 4;
        const RenderResult reference = render(world, options);
        RenderState state = initial_state(c.scene.settings, options);
        // Each call renders at least three tiles: more stops than tiles would mean no progress.
        const std::size_t most_stops =
            state.tile_passes.size() *
            std::size_t(pass_count(c.scene.settings.samples_per_pixel, state.pass_size));
        RenderResult r;
        std::size_t stops = 0;
        do {
            // Stop a few tiles after the render starts again: wherever that falls, tiles in
            // flight finish and the rest of the pass waits for the next call.
            RenderProgress progress;
            std::atomic<bool> done = false;
            std::thread stopper([&] {
                while (!done && progress.tiles_total == 0) std::this_thread::yield();
                const int start = progress.tiles_done;  // set before tiles_total
                while (!done && progress.tiles_done < start + 3) std::this_thread::yield();
                progress.cancel = true;
            });
            r = render(world, options, &progress, &state);
            done = true;
            stopper.join();
            if (!r.complete) {
                ++stops;
                // Tiles ahead of the others: stopped between the tiles of a pass.
                for (const int tile : state.tile_passes) mid_pass += tile - state.passes_done();
            }
            ASSERT_LE(stops, most_stops) << c.name;
        } while (!r.complete);
        expect_same_render(r, reference, c.name);
    }
    EXPECT_GT(mid_pass, 0) << "no stop fell between the tiles of a pass";
}

TEST(Passes, CheckpointsSeeEachPassButTheLast) {
    const Case c = cases()[1];
    RenderOptions options = options_of(2, 2);
    std::vector<int> seen;
    options.after_pass = [&](const RenderState& state) { seen.push_back(state.passes_done()); };
    EXPECT_TRUE(render(World(c.scene), options).complete);
    EXPECT_EQ(seen, (std::vector<int>{1, 2, 3}));  // 7 samples in 4 passes
}

}  // namespace
}  // namespace glint
