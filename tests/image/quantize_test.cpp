#include "glint/image/quantize.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

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

// The whole-image quantiser reads the sRGB curve from a table and hands the values near a
// decision's edge to the exact way: its bytes must be quantize_srgb8's, one value at a time. Every
// 101st float from 0 to 1 (700,000 of them, each octave alike), and the special values.
TEST(ImageQuantize, AnImageRowGivesTheBytesOfEachValueQuantisedAlone) {
    std::vector<float> values = {0,
                                 -0.0f,
                                 1,
                                 1.5f,
                                 -1,
                                 std::numeric_limits<float>::infinity(),
                                 std::numeric_limits<float>::quiet_NaN(),
                                 std::numeric_limits<float>::denorm_min(),
                                 0.0031308f,
                                 std::nextafter(0.0031308f, 1.0f),
                                 std::nextafter(1.0f, 0.0f)};
    for (std::uint32_t bits = 0; bits <= std::bit_cast<std::uint32_t>(1.0f); bits += 101)
        values.push_back(std::bit_cast<float>(bits));
    constexpr int kWidth = 1000;
    const int height = int(values.size() / kWidth) + 1;
    Image image(kWidth, height);
    for (std::size_t i = 0; i < values.size(); ++i) {
        const float v = values[i];
        image.pixels[i] = {v, v, v};  // three channels, three dithers
    }
    std::vector<std::uint8_t> row(kWidth * 3);
    for (int y = 0; y < height; ++y) {
        quantize_srgb8_row(image, y, row.data());
        for (int x = 0; x < kWidth; ++x) {
            const float v = image.at(x, y).r;
            for (int c = 0; c < 3; ++c)
                ASSERT_EQ(row[3 * x + c], quantize_srgb8(v, x, y, c))
                    << "value " << v << " at (" << x << ", " << y << ") channel " << c;
        }
    }
    EXPECT_EQ(quantize_srgb8(image).size(), image.pixels.size() * 3);
}

}  // namespace
}  // namespace glint
