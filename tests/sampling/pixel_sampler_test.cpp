#include "glint/sampling/pixel_sampler.h"

#include <gtest/gtest.h>

#include "glint/sampling/random.h"

namespace glint {
namespace {

TEST(PixelSampler, OneSampleSitsAtThePixelCentre) {
    const PixelSampler sampler(SamplerKind::regular, 1, 0);
    EXPECT_EQ(sampler.offset(0), (Point2{0.5f, 0.5f}));
}

TEST(PixelSampler, RegularGridPlacesSamplesAtCellCentres) {
    const PixelSampler sampler(SamplerKind::regular, 9, 0);
    EXPECT_EQ(sampler.offset(0), (Point2{1 / 6.0f, 1 / 6.0f}));
    EXPECT_EQ(sampler.offset(4), (Point2{0.5f, 0.5f}));
    EXPECT_EQ(sampler.offset(5), (Point2{5 / 6.0f, 0.5f}));
    EXPECT_EQ(sampler.offset(8), (Point2{5 / 6.0f, 5 / 6.0f}));
}

TEST(PixelSampler, RegularNeedsASquareCount) {
    EXPECT_TRUE(is_valid_sample_count(SamplerKind::regular, 1));
    EXPECT_TRUE(is_valid_sample_count(SamplerKind::regular, 16));
    EXPECT_FALSE(is_valid_sample_count(SamplerKind::regular, 2));
    EXPECT_FALSE(is_valid_sample_count(SamplerKind::regular, 0));
}

TEST(Random, PureFunctionOfItsCoordinatesAndUniform) {
    EXPECT_EQ(random_float(7, 3, 1, 42), random_float(7, 3, 1, 42));
    EXPECT_NE(random_float(7, 3, 1, 42), random_float(7, 3, 2, 42));
    EXPECT_NE(random_float(7, 3, 1, 42), random_float(7, 3, 1, 43));
    double sum = 0;
    int buckets[10] = {};
    const int n = 100000;
    for (int i = 0; i < n; ++i) {
        const float u = random_float(i, 0, 0, 1);
        ASSERT_GE(u, 0);
        ASSERT_LT(u, 1);
        sum += u;
        ++buckets[int(u * 10)];
    }
    EXPECT_NEAR(sum / n, 0.5, 0.005);
    for (int b : buckets) EXPECT_NEAR(b, n / 10, 400);  // about 4 standard deviations
}

}  // namespace
}  // namespace glint
