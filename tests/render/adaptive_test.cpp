// Adaptive sampling: pixels without noise stop at the fewest samples, noisy ones take more up
// to the most, the image of samples taken says so, and the result does not depend on threads.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

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
    scene.lights.push_back(*rectangle_light({-1, 3, 0}, {2, 0, 0}, {0, 0, 2}));
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

// A pixel's red channel over renders with several seeds: its mean and the variance of that mean.
struct PixelMeans {
    std::vector<double> mean, variance_of_mean;
};

PixelMeans render_means(const Scene& scene, int renders, std::uint64_t first_seed) {
    const World world(scene);
    const std::size_t pixels = std::size_t(scene.settings.width) * scene.settings.height;
    std::vector<double> sum(pixels), squares(pixels);
    for (int i = 0; i < renders; ++i) {
        RenderOptions options;
        options.seed = first_seed + std::uint64_t(i);
        const Image image = render(world, options).image;
        for (std::size_t p = 0; p < pixels; ++p) {
            sum[p] += image.pixels[p].r;
            squares[p] += double(image.pixels[p].r) * image.pixels[p].r;
        }
    }
    PixelMeans m;
    for (std::size_t p = 0; p < pixels; ++p) {
        const double mean = sum[p] / renders;
        const double variance = std::max(0.0, (squares[p] - renders * mean * mean) / (renders - 1));
        m.mean.push_back(mean);
        m.variance_of_mean.push_back(variance / renders);
    }
    return m;
}

// Adaptive against non-adaptive renders, pixel by pixel, with each filter: the mean of adaptive
// renders over seeds agrees with that of non-adaptive renders of many samples, within the noise
// of both. Splatted through a filter wider than a pixel, a background pixel beside the floor
// that stopped at the fewest samples took most of its weight from its neighbours' many samples.
// The threshold is low enough that only flat pixels stop early: a noisy pixel that stops when
// its first samples happen to agree is biased whatever the filter.
TEST(AdaptiveSampling, AgreesWithTheNonAdaptiveImagePixelByPixelWithEveryFilter) {
    constexpr int kMost = 64, kFewest = 8, kAdaptiveRenders = 8;
    constexpr int kReferenceSamples = 256, kReferenceRenders = 4;
    const FilterSpec filters[] = {{FilterKind::box, 0.5f},
                                  {FilterKind::box, 1},
                                  {FilterKind::tent, 1},
                                  {FilterKind::gaussian, 1.5f},
                                  {FilterKind::mitchell, 2}};
    for (const FilterSpec& filter : filters) {
        Scene adaptive = half_noisy(kMost, kFewest);
        adaptive.settings.adaptive->threshold = 0.005f;
        adaptive.settings.filter = filter;
        Scene reference = adaptive;
        reference.settings.adaptive.reset();
        reference.settings.samples_per_pixel = kReferenceSamples;
        const PixelMeans a = render_means(adaptive, kAdaptiveRenders, 1);
        const PixelMeans r = render_means(reference, kReferenceRenders, 100);
        // Near the image's edge the adaptive pixels' filter reaches past it, where the splatted
        // ones have no samples (docs/scene-format.md#adaptive-sampling).
        const int border = int(std::ceil(filter.radius - 0.5f));
        const int width = adaptive.settings.width, height = adaptive.settings.height;
        int failures = 0;
        for (int y = border; y < height - border; ++y)
            for (int x = border; x < width - border; ++x) {
                const std::size_t p = std::size_t(y) * width + x;
                // Five standard errors, and a little for the bias of stopping on the samples
                // themselves (a pixel stops when its samples happen to agree).
                const double allowed =
                    5 * std::sqrt(a.variance_of_mean[p] + r.variance_of_mean[p]) +
                    0.01 * r.mean[p] + 1e-4;
                if (std::abs(a.mean[p] - r.mean[p]) > allowed) {
                    ++failures;
                    ADD_FAILURE() << "filter " << int(filter.kind) << " radius " << filter.radius
                                  << ": pixel (" << x << ", " << y << ") adaptive " << a.mean[p]
                                  << ", non-adaptive " << r.mean[p] << ", allowed " << allowed;
                }
                if (failures > 10) return;
            }
    }
}

TEST(AdaptiveSampling, WithoutItEveryPixelTakesEverySample) {
    Scene scene = half_noisy(16, 4);
    scene.settings.adaptive.reset();
    const RenderResult r = render(World(scene), kRecordSamples);
    for (const Color& c : r.samples_taken.pixels) EXPECT_EQ(c.r, 16);
}

}  // namespace
}  // namespace glint
