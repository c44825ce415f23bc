// The render loop: images that do not depend on thread count or tile size, and ray counts.
#include "glint/render/render.h"

#include <gtest/gtest.h>

#include "glint/scene/yaml/yaml_scene_loader.h"

namespace glint {
namespace {

Scene showcase(int width, int height) {
    Scene scene = load_yaml_scene(std::string(GLINT_SOURCE_DIR) + "/scenes/showcase.yaml");
    scene.settings.width = width;
    scene.settings.height = height;
    return scene;
}

// A film in a working space of gamma 2 or sRGB's: a background of 0.5 is 0.25, or 0.214 (sRGB's
// 0.5 in linear light), in the image.
TEST(Render, TheImageIsDecodedFromTheWorkingSpace) {
    Scene scene;
    scene.settings.width = 4;
    scene.settings.height = 3;
    scene.settings.background = Color::gray(0.5f);
    scene.settings.working_space = {WorkingSpace::Transfer::gamma, 2};
    const RenderResult gamma = render(World(scene), RenderOptions{});
    EXPECT_FLOAT_EQ(gamma.image.pixels[5].g, 0.25f);
    scene.settings.working_space = {WorkingSpace::Transfer::srgb, 1};
    const RenderResult srgb = render(World(scene), RenderOptions{});
    EXPECT_NEAR(srgb.image.pixels[5].g, 0.21404f, 1e-5f);
}

TEST(Render, ImageIsIdenticalForOneAndManyThreadsAndAnyTileSize) {
    const World world(showcase(96, 72));
    RenderOptions one_thread;
    one_thread.threads = 1;
    const RenderResult reference = render(world, one_thread);
    for (const auto& [threads, tile_size] : {std::pair{2, 16}, std::pair{4, 7}, std::pair{8, 1}}) {
        RenderOptions options;
        options.threads = threads;
        options.tile_size = tile_size;
        const RenderResult r = render(world, options);
        ASSERT_EQ(r.image.pixels.size(), reference.image.pixels.size());
        // Bit for bit: operator== on floats, not a tolerance.
        EXPECT_TRUE(r.image.pixels == reference.image.pixels)
            << threads << " threads, tiles of " << tile_size;
        EXPECT_EQ(r.rays, reference.rays);
    }
}

TEST(Render, FilteredStochasticImageIsIdenticalForAnyThreadsAndTileSize) {
    // Jittered samples through a Gaussian reach across pixel and tile borders; the film's exact
    // sums keep the image the same bit for bit.
    Scene scene = showcase(48, 36);
    scene.settings.sampler = SamplerKind::jittered;
    scene.settings.samples_per_pixel = 5;
    scene.settings.filter = FilterSpec{FilterKind::gaussian, 1.5f};
    const World world(scene);
    RenderOptions one_thread;
    one_thread.threads = 1;
    one_thread.seed = 7;
    const RenderResult reference = render(world, one_thread);
    for (const auto& [threads, tile_size] : {std::pair{2, 16}, std::pair{3, 5}, std::pair{4, 1}}) {
        RenderOptions options = one_thread;
        options.threads = threads;
        options.tile_size = tile_size;
        EXPECT_TRUE(render(world, options).image.pixels == reference.image.pixels)
            << threads << " threads, tiles of " << tile_size;
    }
}

TEST(Render, SeedChangesTheNoiseOfRandomSamplersOnly) {
    for (const SamplerKind kind :
         {SamplerKind::jittered, SamplerKind::sobol, SamplerKind::regular}) {
        Scene scene = showcase(24, 18);
        scene.settings.sampler = kind;
        scene.settings.samples_per_pixel = 4;
        const World world(scene);
        RenderOptions a, b;
        b.seed = 1;
        const bool same = render(world, a).image.pixels == render(world, b).image.pixels;
        EXPECT_EQ(same, kind == SamplerKind::regular) << int(kind);
    }
}

TEST(Render, EveryAccelerationStructureGivesTheSameImage) {
    const Scene scene = showcase(64, 48);
    const RenderResult reference = render(World(scene, AccelKind::list), {});
    for (const std::string_view name : accel_names()) {
        const RenderResult r = render(World(scene, *accel_from_name(name)), {});
        EXPECT_TRUE(r.image.pixels == reference.image.pixels) << name;
        EXPECT_EQ(r.rays, reference.rays) << name;
    }
}

TEST(Render, ShadowAccelerationDoesNotChangeTheImage) {
    // Point lights over spheres and a box (the showcase), and over meshes, which light buffers
    // list whole when small and leave to the structure when large.
    for (const char* file : {"/scenes/showcase.yaml", "/scenes/features/meshes.yaml"}) {
        Scene scene = load_yaml_scene(std::string(GLINT_SOURCE_DIR) + file);
        scene.settings.width = 64;
        scene.settings.height = 48;
        scene.settings.samples_per_pixel = 1;
        const RenderResult reference = render(World(scene), {});
        for (const ShadowAcceleration shadows :
             {ShadowAcceleration{true, false}, ShadowAcceleration{true, true}}) {
            const RenderResult r = render(World(scene, AccelKind::bvh, shadows), {});
            EXPECT_TRUE(r.image.pixels == reference.image.pixels)
                << file << (shadows.occluder_cache ? " with" : " without") << " the cache";
            EXPECT_EQ(r.rays, reference.rays) << file;
        }
    }
}

TEST(Render, CountsOnePrimaryRayPerSample) {
    Scene scene = showcase(20, 10);
    scene.settings.samples_per_pixel = 4;
    const RenderResult r = render(World(scene), {});
    EXPECT_EQ(r.rays[RayKind::primary], 20u * 10 * 4);
    EXPECT_LE(r.rays.primary_hits, r.rays[RayKind::primary]);
    EXPECT_GT(r.rays[RayKind::shadow], 0u);
    EXPECT_TRUE(r.complete);
    EXPECT_EQ(r.bad_samples.count, 0u);
}

TEST(Render, CancelledRenderSkipsTheRemainingTilesAndSaysSo) {
    const World world(showcase(64, 64));
    RenderProgress progress;
    progress.cancel = true;
    const RenderResult r = render(world, {}, &progress);
    EXPECT_FALSE(r.complete);
    EXPECT_EQ(progress.tiles_done, 0);
    EXPECT_EQ(r.image.width, 64);
    EXPECT_EQ(r.rays[RayKind::primary], 0u);
}

TEST(Render, NonFiniteSamplesAreCountedAndLeftOut) {
    // An emission of infinity makes every sample that sees the sphere non-finite.
    Scene scene;
    scene.settings.width = 8;
    scene.settings.height = 8;
    scene.camera.from = {0, 0, -5};
    scene.camera.at = {0, 0, 0};
    Material hot;
    hot.emission = Color::gray(kInfinity);
    scene.materials.push_back(hot);
    scene.objects.push_back({Sphere{{0, 0, 0}, 1}, 0});
    const RenderResult r = render(World(scene), {});
    EXPECT_GT(r.bad_samples.count, 0u);
    ASSERT_TRUE(r.bad_samples.first);
    for (const Color& c : r.image.pixels) EXPECT_TRUE(is_finite(c));
    // The first bad sample in scanline order: in the topmost row the sphere covers, row 2
    // (its centre ray passes 5 sin(atan(0.375 tan 22.5)) = 0.77 from the sphere's centre).
    EXPECT_EQ(r.bad_samples.first->y, 2);
}

}  // namespace
}  // namespace glint
