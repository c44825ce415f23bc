#include "glint/image/ppm_io.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "glint/image/png_io.h"
#include "glint/image/srgb.h"
#include "test_files.h"

namespace glint::ppm_io_test {
namespace {

using namespace std::string_literals;

Image random_image(int width, int height, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> value(-0.1f, 1.1f);
    Image image(width, height);
    for (Color& c : image.pixels) c = {value(rng), value(rng), value(rng)};
    return image;
}

float from_level(int v, int maxval) { return srgb_to_linear(float(v) / float(maxval)); }

TEST(Ppm, AsciiLayoutOfATwoByOneImage) {
    const auto path = testing::fresh_test_dir() / "two.ppm";
    Image image(2, 1);
    image.at(0, 0) = {1, 0, 0};
    image.at(1, 0) = {0, 0, 1};
    write_ppm(path, image, PpmEncoding::ascii);
    EXPECT_EQ(testing::read_file(path), "P3\n2 1\n255\n255 0 0\n0 0 255\n");
}

TEST(Ppm, BinaryLayoutOfATwoByOneImage) {
    const auto path = testing::fresh_test_dir() / "two.ppm";
    Image image(2, 1);
    image.at(0, 0) = {1, 0, srgb_to_linear(128.0f / 255)};
    image.at(1, 0) = {0, 1, 0};
    write_ppm(path, image);
    EXPECT_EQ(testing::read_file(path), "P6\n2 1\n255\n\xff\x00\x80\x00\xff\x00"s);
}

TEST(Ppm, RoundTripIsWithinOneLevelInSrgbForBothEncodings) {
    const auto dir = testing::fresh_test_dir();
    const Image image = random_image(19, 11, 1);
    for (const auto encoding : {PpmEncoding::binary, PpmEncoding::ascii}) {
        const auto path = dir / (encoding == PpmEncoding::ascii ? "a.ppm" : "b.ppm");
        write_ppm(path, image, encoding);
        const Image back = read_ppm(path);
        ASSERT_EQ(back.width, 19);
        ASSERT_EQ(back.height, 11);
        for (std::size_t i = 0; i < image.pixels.size(); ++i) {
            const Color a = image.pixels[i], b = back.pixels[i];
            EXPECT_LT(std::abs(linear_to_srgb(a.r) - linear_to_srgb(b.r)), 1.0f / 255 + 1e-6f);
            EXPECT_LT(std::abs(linear_to_srgb(a.g) - linear_to_srgb(b.g)), 1.0f / 255 + 1e-6f);
            EXPECT_LT(std::abs(linear_to_srgb(a.b) - linear_to_srgb(b.b)), 1.0f / 255 + 1e-6f);
        }
    }
}

TEST(Ppm, HoldsTheSameDitheredBytesAsPngAndAsItsAsciiForm) {
    const auto dir = testing::fresh_test_dir();
    const Image image = random_image(16, 9, 2);
    write_ppm(dir / "b.ppm", image, PpmEncoding::binary);
    write_ppm(dir / "a.ppm", image, PpmEncoding::ascii);
    write_png(dir / "c.png", image);
    const Image binary = read_ppm(dir / "b.ppm");
    EXPECT_EQ(binary.pixels, read_ppm(dir / "a.ppm").pixels);
    EXPECT_EQ(binary.pixels, read_png(dir / "c.png").pixels);
}

TEST(Ppm, ReadsCommentsAndAnyMaxval) {
    const auto path = testing::fresh_test_dir() / "comments.ppm";
    testing::write_file(path,
                        "P3\n# made by hand\n2 1 # size\n# maxval next\n15\n15 0 0  0 7 15\n");
    const Image image = read_ppm(path);
    ASSERT_EQ(image.width, 2);
    EXPECT_EQ(image.at(0, 0), Color(1, 0, 0));
    EXPECT_EQ(image.at(1, 0), Color(0, from_level(7, 15), 1));
}

TEST(Ppm, ReadsSixteenBitBinaryBigEndian) {
    const auto path = testing::fresh_test_dir() / "deep.ppm";
    testing::write_file(path, "P6 1 1 65535\n\xff\xff\x01\x00\x00\x02"s);
    const Image image = read_ppm(path);
    EXPECT_EQ(image.at(0, 0), Color(1, from_level(256, 65535), from_level(2, 65535)));
}

TEST(Ppm, MalformedFilesNameTheFileAndTheProblem) {
    const auto dir = testing::fresh_test_dir();
    const auto expect_error = [&](const std::string& name, const std::string& contents,
                                  const std::string& fragment) {
        SCOPED_TRACE(name);
        const auto path = dir / name;
        testing::write_file(path, contents);
        testing::expect_image_error([&] { read_ppm(path); }, path, fragment);
    };
    expect_error("magic.ppm", "P5\n1 1\n255\n\x01",
                 "malformed PPM: bad magic number \"P5\"; expected P3 or P6");
    expect_error("empty.ppm", "", "bad magic number \"\"");
    expect_error("negative.ppm", "P6\n-2 1\n255\n",
                 "width must be an integer from 1 to 1048576, got \"-2\"");
    expect_error("zero.ppm", "P3\n0 1\n255\n", "width must be an integer from 1 to");
    expect_error("zero_height.ppm", "P3\n1 0\n255\n", "height must be an integer from 1 to");
    expect_error("maxval0.ppm", "P6\n1 1\n0\n\x00\x00\x00"s,
                 "maxval must be an integer from 1 to 65535, got \"0\"");
    expect_error("maxval_big.ppm", "P6\n1 1\n70000\n", "maxval must be an integer from 1 to 65535");
    expect_error("no_maxval.ppm", "P6\n1 1\n", "header ends before the maxval");
    expect_error("short.ppm", "P6\n2 2\n255\n\x01\x02\x03\x04\x05",
                 "pixel data truncated: expected 12 bytes, found 5");
    expect_error("short16.ppm", "P6\n1 1\n1000\n\x01\x02\x03\x04\x05",
                 "pixel data truncated: expected 6 bytes, found 5");
    expect_error("no_gap.ppm", "P6\n1 1\n255", "no single whitespace byte");
    expect_error("short_ascii.ppm", "P3\n2 1\n255\n1 2 3 4 5\n",
                 "pixel data truncated: expected 6 samples, found 5");
    expect_error("over_maxval.ppm", "P6\n1 1\n100\n\x01\xc8\x02",
                 "sample 200 at pixel (0, 0) exceeds maxval 100");
    expect_error("bad_sample.ppm", "P3\n2 1\n255\n1 2 3 4 5x 6\n",
                 "bad sample \"5x\" at pixel (1, 0)");
    expect_error("ascii_over_maxval.ppm", "P3\n1 1\n9\n1 2 10\n", "bad sample \"10\"");
    expect_error("huge.ppm", "P6\n1048576 1048576\n255\n", "larger than glint accepts");
}

TEST(Ppm, MissingFileIsAnError) {
    const auto path = testing::fresh_test_dir() / "missing.ppm";
    testing::expect_image_error([&] { read_ppm(path); }, path, "cannot open for reading");
}

}  // namespace
}  // namespace glint::ppm_io_test
