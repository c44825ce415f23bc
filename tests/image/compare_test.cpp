#include "glint/image/compare.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "glint/image/image_error.h"
#include "glint/image/srgb.h"

namespace glint {
namespace {

TEST(Compare, IdenticalImagesDoNotDiffer) {
    const Image a(3, 2, Color(0.1f, 0.5f, 0.9f));
    const ImageDifference d = compare_images(a, a);
    EXPECT_EQ(d.rmse, 0);
    EXPECT_EQ(d.max_abs, 0);
    EXPECT_EQ(d.fraction_over_threshold, 0);
    EXPECT_EQ(d.width, 3);
    EXPECT_EQ(d.height, 2);
    EXPECT_EQ(d.threshold, 2.0 / 255);
}

TEST(Compare, WorkedExampleOneChannelOfOnePixel) {
    // 2x2 black against the same with one red pixel: one of 12 channel values differs by 1.
    const Image a(2, 2);
    Image b = a;
    b.at(1, 0) = {1, 0, 0};
    const ImageDifference d = compare_images(a, b);
    // Within 1e-6: srgb.h works in float, where linear 1 encodes to 0.99999994.
    EXPECT_NEAR(d.rmse, std::sqrt(1.0 / 12), 1e-6);  // 0.288675
    EXPECT_NEAR(d.max_abs, 1, 1e-6);
    EXPECT_DOUBLE_EQ(d.fraction_over_threshold, 0.25);
}

TEST(Compare, WorkedExampleWithASmallDifferenceUnderTheThreshold) {
    // Pixel (0, 1) differs by 0.5 in all three encoded channels; pixel (1, 1) by 1/255 in green,
    // which is under the default threshold of 2/255.
    const Image a(2, 2);
    Image b = a;
    b.at(0, 1) = Color::gray(srgb_to_linear(0.5f));
    b.at(1, 1) = {0, srgb_to_linear(1.0f / 255), 0};
    const ImageDifference d = compare_images(a, b);
    EXPECT_NEAR(d.rmse, std::sqrt((3 * 0.25 + 1.0 / (255 * 255)) / 12), 1e-6);  // 0.250033
    EXPECT_NEAR(d.max_abs, 0.5, 1e-6);
    EXPECT_DOUBLE_EQ(d.fraction_over_threshold, 0.25);
    EXPECT_DOUBLE_EQ(compare_images(a, b, 0.5 / 255).fraction_over_threshold, 0.5);
}

TEST(Compare, DifferencesAreMeasuredOnClampedSrgbValues) {
    const Image dark_a(1, 1, Color::gray(0.001f)), dark_b(1, 1, Color::gray(0.002f));
    EXPECT_NEAR(compare_images(dark_a, dark_b).max_abs, 12.92 * 0.001, 1e-6);  // linear segment
    const Image bright_a(1, 1, Color::gray(2)), bright_b(1, 1, Color::gray(50));
    EXPECT_EQ(compare_images(bright_a, bright_b).max_abs, 0);
}

TEST(Compare, NanDiffersFromEveryNumberButNotFromNan) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const Image a(1, 1, Color(nan, 0, nan));
    const Image b(1, 1, Color(nan, 0, 0));
    const ImageDifference d = compare_images(a, b);
    EXPECT_DOUBLE_EQ(d.max_abs, 1);
    EXPECT_DOUBLE_EQ(d.rmse, std::sqrt(1.0 / 3));
    EXPECT_DOUBLE_EQ(d.fraction_over_threshold, 1);
}

TEST(Compare, SizesMustMatch) {
    try {
        compare_images(Image(2, 2), Image(3, 2));
        FAIL() << "expected an ImageError";
    } catch (const ImageError& e) {
        EXPECT_STREQ(e.what(), "cannot compare images of different sizes: 2x2 and 3x2");
    }
    EXPECT_THROW(difference_image(Image(2, 2), Image(2, 1)), ImageError);
}

TEST(Compare, DifferenceImageShowsFourTimesTheEncodedDifference) {
    const Image a(2, 1);
    Image b = a;
    b.at(0, 0) = {srgb_to_linear(0.1f), 0, 0};
    b.at(1, 0) = {0, srgb_to_linear(0.5f), 0};
    const Image d = difference_image(a, b);
    ASSERT_EQ(d.width, 2);
    ASSERT_EQ(d.height, 1);
    EXPECT_NEAR(linear_to_srgb(d.at(0, 0).r), 0.4, 1e-6);
    EXPECT_EQ(d.at(0, 0).g, 0);
    EXPECT_EQ(d.at(1, 0).g, 1);  // 4 x 0.5, clamped
}

TEST(Compare, DescribeGivesTheNumbersInOneLine) {
    Image a(2, 2);
    Image b = a;
    b.at(1, 0) = {1, 0, 0};
    EXPECT_EQ(describe(compare_images(a, b)),
              "2x2 pixels: rmse 0.2887 (73.61/255), max 1 (255.0/255), 25.00% of pixels (1) "
              "differ by more than 0.007843 (2.0/255)");
}

}  // namespace
}  // namespace glint
