// Adaptive sampling: pixels without noise stop at the fewest samples, noisy ones take more up
// to the most, the image of samples taken says so, and the result does not depend on threads.
#include <gtest/gtest.h>

#include "glint/render/render.h"

namespace glint {
namespace {

const RenderOptions kRecordSamples{.record_samples_taken = true};

// A floor lit by a large area light, half of it behind a wall edge: the left of the image is a
// flat background (no noise), the right a floor with a soft penumbra (noise).
Scene half_noisy(int most, int fewest) {
    Scene scene;
    scene.settings.width = 32;
    scene.settings.height = 16;
    scene.settings.integrator = IntegratorKind::distributed;
    scene.settings.samples_per_pixel = most;
    scene.settings.adaptive = AdaptiveSampling{0.02f, fewest};
    scene.settings.background = Color::gray(0.5f);
    scene.camera.from = {0, 5, 0};
    scene.camera.at = {0, 0, 0};
    scene.camera.up = {0, 0, 1};
    scene.camera.fov = 60;
    Material floor;
    floor.ka = 0, floor.kd = 1;
    scene.materials.push_back(floor);
    // The floor covers x < 0 only (the image's right, as u = forward x up = -x).
    scene.objects.push_back({Box{{-10, -1, -10}, {0, 0, 10}}, 0});
    scene.objects.push_back({Box{{-10, 0, 0}, {0, 1, 0.2f}}, 0});  // a wall casting a penumbra
    AreaLight light;
    light.shape = RectangleLight{{-1, 3, 0}, {2, 0, 0}, {0, 0, 2}};
    scene.lights.push_back(light);
    return scene;
}

TEST(AdaptiveSampling, FlatPixelsStopAtTheFewestAndNoisyOnesTakeMore) {
    const RenderResult r = render(World(half_noisy(256, 8)), kRecordSamples);
    const Image& n = r.samples_taken;
    int fewest = 0, more = 0;
    for (int y = 0; y < n.height; ++y)
        for (int x = 0; x < n.width; ++x) {
            const float taken = n.at(x, y).r;
            ASSERT_GE(taken, 8);
            ASSERT_LE(taken, 256);
            // The background (left half) has no noise at all.
            if (x < n.width / 2 - 1) {
                EXPECT_EQ(taken, 8) << x << ", " << y;
            }
            fewest += taken == 8;
            more += taken > 8;
        }
    EXPECT_GT(fewest, n.width * n.height / 2 - 2 * n.height);
    EXPECT_GT(more, n.width * n.height / 8);  // the penumbra's pixels
    // The eye rays are the samples taken.
    double total = 0;
    for (const Color& c : n.pixels) total += c.r;
    EXPECT_EQ(r.rays.traced[std::size_t(RayKind::primary)], std::uint64_t(total));
}

TEST(AdaptiveSampling, ImagesAndCountsDoNotDependOnThreads) {
    const World world(half_noisy(64, 4));
    RenderOptions one = kRecordSamples, two = kRecordSamples;
    one.threads = 1;
    two.threads = 2;
    two.tile_size = 8;
    const RenderResult a = render(world, one), b = render(world, two);
    EXPECT_EQ(a.image.pixels, b.image.pixels);
    EXPECT_EQ(a.samples_taken.pixels, b.samples_taken.pixels);
}

TEST(AdaptiveSampling, WithoutItEveryPixelTakesEverySample) {
    Scene scene = half_noisy(16, 4);
    scene.settings.adaptive.reset();
    const RenderResult r = render(World(scene), kRecordSamples);
    for (const Color& c : r.samples_taken.pixels) EXPECT_EQ(c.r, 16);
}

}  // namespace
}  // namespace glint
