// The path tracer against answers known exactly: a furnace whose walls emit and reflect, direct
// lighting that is the distributed integrator's, light that one wall reflects onto another, and
// images that do not depend on the thread count.
#include "glint/render/integrators/path.h"

#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

#include "common/under_sanitizer.h"
#include "glint/render/render.h"
#include "global_illumination_scenes.h"

namespace glint {
namespace {

using testing::directly_lit;
using testing::furnace;
using testing::red_wall;

TEST(PathTracing, AFurnaceOfEmittingWallsGivesLeOverOneMinusAlbedo) {
    for (const float albedo : {0.5f, 0.8f}) {
        const Color le{0.2f, 0.1f, 0.05f};
        const RenderResult r = render(World(furnace(albedo, le)), {});
        // Russian roulette and the light's weighting leave noise; its mean is exact.
        SCOPED_TRACE(albedo);
        testing::expect_furnace_answer(r.image, le / (1 - albedo));
        // The walls light themselves: shadow rays and scattered rays both.
        EXPECT_GT(r.rays[RayKind::shadow], 0u);
        EXPECT_GT(r.rays[RayKind::diffuse], 0u);
    }
}

TEST(PathTracing, MaxDepthCutsTheSumOfBounces) {
    // max_depth 2: what the eye sees, and two bounces' worth: Le (1 + rho + rho^2).
    Scene scene = furnace(0.5f, Color::gray(1));
    scene.settings.max_depth = 2;
    const RenderResult r = render(World(scene), {});
    Color mean;
    for (const Color& c : r.image.pixels) mean += c / float(r.image.pixels.size());
    EXPECT_NEAR(mean.r, 1.75, 0.01 * 1.75);
}

// With one light picked by power at each point, and with every light (next_event: all), whose
// shadow rays are one for each of the three lights where there was one in all.
class OneBounce : public ::testing::TestWithParam<NextEventStrategy> {};

TEST_P(OneBounce, IsTheDistributedIntegratorsDirectLighting) {
    // Four renders of each with different seeds. A pixel's noise is not independent of its
    // neighbours' (the renders of some seeds come out alike), so the noise of a 4 x 4 block's
    // mean is measured across the seeds, pooled over the blocks for a steady estimate; the
    // means of the two integrators must agree within 5 standard errors of their difference.
    constexpr int kSeeds = 4, kBlock = 4;
    std::uint64_t shadow_rays = 0;
    // Each block's mean red, a vector a seed.
    const auto block_means = [&](IntegratorKind kind) {
        Scene scene = directly_lit(kind);
        scene.settings.next_event = GetParam();
        const World world(scene);
        std::vector<std::vector<double>> means;
        for (int seed = 1; seed <= kSeeds; ++seed) {
            RenderOptions options;
            options.seed = std::uint64_t(seed);
            const RenderResult r = render(world, options);
            if (seed == 1) shadow_rays = r.rays[RayKind::shadow];
            std::vector<double>& m = means.emplace_back();
            for (int by = 0; by < r.image.height; by += kBlock)
                for (int bx = 0; bx < r.image.width; bx += kBlock) {
                    double sum = 0;
                    for (int y = by; y < by + kBlock; ++y)
                        for (int x = bx; x < bx + kBlock; ++x) sum += r.image.at(x, y).r;
                    m.push_back(sum / (kBlock * kBlock));
                }
        }
        return means;
    };
    const auto distributed = block_means(IntegratorKind::distributed);
    const auto path = block_means(IntegratorKind::path);
    // With the same seed the eye rays and their hits are the same: all lights send three shadow
    // rays where one picked light sends one.
    Scene one = directly_lit(IntegratorKind::path);
    RenderOptions first_seed;
    first_seed.seed = 1;
    const std::uint64_t picked = render(World(one), first_seed).rays[RayKind::shadow];
    if (GetParam() == NextEventStrategy::all) {
        EXPECT_GT(double(shadow_rays), 2.5 * double(picked));
        EXPECT_LE(shadow_rays, 3 * picked);
    }
    const std::size_t blocks = path[0].size();
    std::vector<double> path_mean(blocks), distributed_mean(blocks);
    double variance = 0;  // of one render's block mean, both integrators', pooled
    for (std::size_t b = 0; b < blocks; ++b) {
        for (int s = 0; s < kSeeds; ++s) {
            path_mean[b] += path[s][b] / kSeeds;
            distributed_mean[b] += distributed[s][b] / kSeeds;
        }
        for (int s = 0; s < kSeeds; ++s)
            variance += std::pow(path[s][b] - path_mean[b], 2) +
                        std::pow(distributed[s][b] - distributed_mean[b], 2);
    }
    variance /= double(blocks) * (kSeeds - 1);
    const double error = std::sqrt(variance / kSeeds);
    for (std::size_t b = 0; b < blocks; ++b)
        EXPECT_NEAR(path_mean[b], distributed_mean[b], 5 * error + 0.002)
            << "block " << b << ", standard error " << error;
}

INSTANTIATE_TEST_SUITE_P(PathTracing, OneBounce,
                         ::testing::Values(NextEventStrategy::one, NextEventStrategy::all),
                         [](const ::testing::TestParamInfo<NextEventStrategy>& strategy) {
                             return strategy.param == NextEventStrategy::one
                                        ? std::string("OneLightPickedByPower")
                                        : std::string("EveryLight");
                         });

TEST(PathTracing, AWhiteFloorBesideARedWallTurnsRed) {
    const auto redness = [](const Image& image) {
        Color sum;
        for (int x = 0; x < image.width; ++x) sum += image.at(x, image.height - 1);  // floor
        return sum.r / sum.g;
    };
    EXPECT_GT(redness(render(World(red_wall(IntegratorKind::path)), {}).image), 1.1);
    EXPECT_NEAR(redness(render(World(red_wall(IntegratorKind::distributed)), {}).image), 1, 1e-4);
}

// A light set into a ceiling emits downwards only: a surface above it gets nothing from it, in
// the distributed integrator and the path tracer alike, and its back is dark to the eye.
TEST(PathTracing, AOneSidedEmitterLightsOnlyItsFront) {
    for (const IntegratorKind kind : {IntegratorKind::distributed, IntegratorKind::path}) {
        Scene scene = directly_lit(kind);
        scene.lights.clear();
        scene.materials[1].emits_both_sides = false;
        // The disk faces down; the camera looks at it from below, then from above.
        scene.settings.max_depth = 1;
        scene.camera.from = {1.5f, 0.5f, -1};
        scene.camera.at = {1.5f, 1.5f, 0};
        const Image below = render(World(scene), {}).image;
        EXPECT_GT(below.at(12, 8).r, 1) << "its front glows";
        scene.camera.from = {1.5f, 2.5f, -1};
        const Image above = render(World(scene), {}).image;
        EXPECT_EQ(above.at(12, 8).r, 0) << "its back is dark";
        // The floor below is lit by it.
        scene.camera.from = {0, 4, -6};
        scene.camera.at = {1.5f, 0, 0};
        EXPECT_GT(render(World(scene), {}).image.at(12, 8).r, 0);
    }
}

TEST(PathTracing, TheImageDoesNotDependOnThreadsOrTiles) {
    const World world(red_wall(IntegratorKind::path));
    RenderOptions one, two;
    one.threads = 1;
    two.threads = 2;
    two.tile_size = 3;
    EXPECT_EQ(render(world, one).image.pixels, render(world, two).image.pixels);
    RenderOptions other_seed = one;
    other_seed.seed = 1;
    EXPECT_NE(render(world, one).image.pixels, render(world, other_seed).image.pixels);
}

}  // namespace
}  // namespace glint
