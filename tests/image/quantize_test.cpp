#include "glint/image/quantize.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "glint/image/srgb.h"

namespace glint {
namespace {

TEST(ImageQuantize, ExtremesClampAndNanIsBlack) {
    const float inf = std::numeric_limits<float>::infinity();
    EXPECT_EQ(quantize_srgb8(0, 3, 4, 0), 0);
    EXPECT_EQ(quantize_srgb8(1, 3, 4, 1), 255);
    EXPECT_EQ(quantize_srgb8(7.5f, 3, 4, 2), 255);
    EXPECT_EQ(quantize_srgb8(-2, 3, 4, 0), 0);
    EXPECT_EQ(quantize_srgb8(inf, 3, 4, 0), 255);
    EXPECT_EQ(quantize_srgb8(-inf, 3, 4, 0), 0);
    EXPECT_EQ(quantize_srgb8(std::numeric_limits<float>::quiet_NaN(), 3, 4, 0), 0);
}

TEST(ImageQuantize, DecodedEightBitLevelsComeBackExactly) {
    for (int level = 0; level < 256; ++level) {
        const float linear = srgb_to_linear(float(level) / 255);
        for (int x = 0; x < 16; ++x) {
            ASSERT_EQ(quantize_srgb8(linear, x, 2 * x + 1, x % 3), level) << "at x " << x;
        }
    }
}

TEST(ImageQuantize, SameImageGivesSameBytesAndNoiseVariesWithPosition) {
    Image image(64, 32);
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            image.at(x, y) = {float(x) / 64, float(y) / 32, 0.3f};
        }
    }
    const auto first = quantize_srgb8(image);
    EXPECT_EQ(first, quantize_srgb8(image));
    ASSERT_EQ(first.size(), std::size_t(64 * 32 * 3));

    Image flat(16, 16, Color::gray(srgb_to_linear(100.5f / 255)));
    const auto bytes = quantize_srgb8(flat);
    int hundreds = 0;
    for (const auto b : bytes) hundreds += b == 100;
    EXPECT_GT(hundreds, 0);
    EXPECT_LT(hundreds, int(bytes.size()));
}

TEST(ImageQuantize, DitherAveragesToTheTrueValue) {
    for (const double level : {100.3, 17.9, 200.5, 0.25, 254.8}) {
        Image flat(256, 256, Color::gray(srgb_to_linear(float(level / 255))));
        const auto bytes = quantize_srgb8(flat);
        double sum = 0;
        for (const auto b : bytes) {
            ASSERT_TRUE(b == std::floor(level) || b == std::ceil(level)) << int(b);
            sum += b;
        }
        EXPECT_NEAR(sum / double(bytes.size()), level, 0.1) << "level " << level;
    }
}

}  // namespace
}  // namespace glint
