#include "glint/image/pfm_io.h"

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>

#include "test_files.h"

namespace glint::pfm_io_test {

using namespace std::string_literals;

std::string little_endian(float v) {
    const auto bits = std::bit_cast<std::uint32_t>(v);
    return {char(bits), char(bits >> 8), char(bits >> 16), char(bits >> 24)};
}

std::string big_endian(float v) {
    const auto bits = std::bit_cast<std::uint32_t>(v);
    return {char(bits >> 24), char(bits >> 16), char(bits >> 8), char(bits)};
}

bool same_bits(const Image& a, const Image& b) {
    return a.width == b.width && a.height == b.height && a.pixels.size() == b.pixels.size() &&
           std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(Color)) == 0;
}

TEST(Pfm, HeaderTextAndBottomToTopRows) {
    const auto path = testing::fresh_test_dir() / "layout.pfm";
    Image image(2, 2);
    image.at(0, 0) = {1, 2, 3};  // top row
    image.at(1, 0) = {4, 5, 6};
    image.at(0, 1) = {7, 8, 9};  // bottom row: first in the file
    image.at(1, 1) = {10, 11, 12};
    write_pfm(path, image);
    std::string expected = "PF\n2 2\n-1.0\n";
    for (const float v : {7, 8, 9, 10, 11, 12, 1, 2, 3, 4, 5, 6}) expected += little_endian(v);
    EXPECT_EQ(testing::read_file(path), expected);
}

TEST(Pfm, RoundTripIsBitExact) {
    const auto path = testing::fresh_test_dir() / "exact.pfm";
    Image image(3, 2);
    const float values[] = {0.1f,
                            -0.0f,
                            1e30f,
                            -7.25f,
                            std::numeric_limits<float>::denorm_min(),
                            std::numeric_limits<float>::infinity(),
                            std::numeric_limits<float>::quiet_NaN(),
                            65504.5f,
                            1.0f / 3,
                            2.5e-8f,
                            123456.789f,
                            -1e-30f,
                            0.5f,
                            0.25f,
                            42,
                            1,
                            0,
                            3.14159f};
    std::memcpy(image.pixels.data(), values, sizeof values);
    write_pfm(path, image);
    EXPECT_TRUE(same_bits(read_pfm(path), image));
}

TEST(Pfm, ReadsBigEndianAndGrayscale) {
    const auto path = testing::fresh_test_dir() / "gray.pfm";
    // Scale 2.5: positive means big-endian; its magnitude is ignored.
    testing::write_file(path, "Pf\n2 2\n2.5\n" + big_endian(0.5f) + big_endian(-1) + big_endian(8) +
                                  big_endian(0.125f));
    const Image image = read_pfm(path);
    ASSERT_EQ(image.width, 2);
    ASSERT_EQ(image.height, 2);
    EXPECT_EQ(image.at(0, 1), Color::gray(0.5f));  // first in the file: bottom left
    EXPECT_EQ(image.at(1, 1), Color::gray(-1));
    EXPECT_EQ(image.at(0, 0), Color::gray(8));
    EXPECT_EQ(image.at(1, 0), Color::gray(0.125f));
}

TEST(Pfm, ReadsBigEndianColour) {
    const auto path = testing::fresh_test_dir() / "big.pfm";
    testing::write_file(path, "PF 1 1 1.0\n" + big_endian(1) + big_endian(2) + big_endian(3));
    EXPECT_EQ(read_pfm(path).at(0, 0), Color(1, 2, 3));
}

TEST(Pfm, MalformedFilesNameTheFileAndTheProblem) {
    const auto dir = testing::fresh_test_dir();
    const auto expect_error = [&](const std::string& name, const std::string& contents,
                                  const std::string& fragment) {
        SCOPED_TRACE(name);
        const auto path = dir / name;
        testing::write_file(path, contents);
        testing::expect_image_error([&] { read_pfm(path); }, path, fragment);
    };
    const std::string pixel = little_endian(1) + little_endian(2) + little_endian(3);
    expect_error("magic.pfm", "PX\n1 1\n-1.0\n" + pixel,
                 "malformed PFM: bad magic number \"PX\"; expected PF or Pf");
    expect_error("zero_scale.pfm", "PF\n1 1\n0\n" + pixel,
                 "scale must be a non-zero number (negative for little-endian), got \"0\"");
    expect_error("text_scale.pfm", "PF\n1 1\nbig\n" + pixel, "got \"big\"");
    expect_error("nan_scale.pfm", "PF\n1 1\nnan\n" + pixel, "got \"nan\"");
    expect_error("half_scale.pfm", "PF\n1 1\n-1.0x\n" + pixel, "got \"-1.0x\"");
    expect_error("no_scale.pfm", "PF\n1 1\n", "got \"\"");
    expect_error("width.pfm", "PF\n-1 1\n-1.0\n" + pixel, "width must be an integer from 1 to");
    expect_error("truncated.pfm", "PF\n2 1\n-1.0\n" + pixel,
                 "pixel data truncated: expected 24 bytes, found 12");
    expect_error("truncated_gray.pfm", "Pf\n2 1\n-1.0\n" + little_endian(1),
                 "expected 8 bytes, found 4");
    expect_error("no_gap.pfm", "PF\n1 1\n-1.0", "no single whitespace byte");
}

}  // namespace glint::pfm_io_test
