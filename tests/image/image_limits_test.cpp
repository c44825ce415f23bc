#include "glint/image/image_limits.h"

#include <gtest/gtest.h>

#include "test_files.h"

namespace glint {
namespace {

TEST(ImageLimits, AcceptsOrdinarySizes) {
    EXPECT_NO_THROW(check_image_size("a.png", 1, 1));
    EXPECT_NO_THROW(check_image_size("a.png", 1920, 1080));
    EXPECT_NO_THROW(
        check_image_size("a.png", kMaxImageDimension, kMaxImagePixels / kMaxImageDimension));
}

TEST(ImageLimits, RejectsEmptyNegativeAndHugeSizes) {
    testing::expect_image_error([] { check_image_size("a.png", 0, 5); }, "a.png",
                                "image size 0x5 is empty or negative");
    testing::expect_image_error([] { check_image_size("a.png", 3, -1); }, "a.png", "3x-1");
    testing::expect_image_error([] { check_image_size("a.png", kMaxImageDimension + 1, 1); },
                                "a.png", "larger than glint accepts");
    testing::expect_image_error([] { check_image_size("a.png", 100000, 100000); }, "a.png",
                                "larger than glint accepts");
}

TEST(ImageLimits, ShapeMustMatchThePixelCount) {
    Image image(2, 2);
    EXPECT_NO_THROW(check_image_shape("a.png", image));
    image.pixels.pop_back();
    testing::expect_image_error([&] { check_image_shape("a.png", image); }, "a.png",
                                "image claims 2x2 pixels but holds 3");
    Image empty;
    testing::expect_image_error([&] { check_image_shape("a.png", empty); }, "a.png",
                                "image size 0x0 is empty");
}

}  // namespace
}  // namespace glint
