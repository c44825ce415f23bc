// Loading texture images with stb_image: sRGB decoding, HDR kept linear, errors naming the file.
#include "glint/image/texture_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "glint/image/image_error.h"
#include "glint/image/image_io.h"

namespace glint {
namespace {

const std::filesystem::path kOut = std::filesystem::path(GLINT_TEST_OUTPUT_DIR) / "texture_file";

std::filesystem::path write_bytes(const std::string& name, const std::string& bytes) {
    std::filesystem::create_directories(kOut);
    const auto path = kOut / name;
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
}

TEST(TextureFile, SpotTextureLoads) {
    const Image image = load_texture_image(std::filesystem::path(GLINT_SOURCE_DIR) /
                                           "tests/data/meshes/spot_texture.png");
    EXPECT_EQ(image.width, 1024);
    EXPECT_EQ(image.height, 1024);
    for (const Color& c : image.pixels) {
        ASSERT_TRUE(c.r >= 0 && c.r <= 1 && c.g >= 0 && c.g <= 1 && c.b >= 0 && c.b <= 1);
    }
}

TEST(TextureFile, EightBitPngIsDecodedFromSrgb) {
    // glint writes PNGs sRGB-encoded; reading one back through stb must give linear values.
    Image image(2, 1);
    image.at(0, 0) = {0.5f, 0.2140f, 1};  // 0.2140 linear is sRGB 128/255
    image.at(1, 0) = {0, 0.0031308f, 0.04f};
    const auto path = kOut / "two.png";
    std::filesystem::create_directories(kOut);
    write_image(path, image);
    const Image back = load_texture_image(path);
    ASSERT_EQ(back.width, 2);
    ASSERT_EQ(back.height, 1);
    // sRGB 188/255 = 0.73725 decodes to 0.50289; 128/255 to 0.21586.
    EXPECT_NEAR(back.at(0, 0).r, 0.5f, 0.005f);
    EXPECT_NEAR(back.at(0, 0).g, 0.21586f, 0.002f);
    EXPECT_EQ(back.at(0, 0).b, 1);
    EXPECT_EQ(back.at(1, 0).r, 0);
}

TEST(TextureFile, HdrStaysLinear) {
    // A 1x1 Radiance RGBE file, flat (uncompressed): (128, 64, 32, exponent 129) means
    // mantissa / 256 * 2^(129 - 128) = (1, 0.5, 0.25).
    std::string hdr = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 1\n";
    hdr += std::string{char(128), char(64), char(32), char(129)};
    const Image image = load_texture_image(write_bytes("one.hdr", hdr));
    ASSERT_EQ(image.width, 1);
    EXPECT_FLOAT_EQ(image.at(0, 0).r, 1.0f);
    EXPECT_FLOAT_EQ(image.at(0, 0).g, 0.5f);
    EXPECT_FLOAT_EQ(image.at(0, 0).b, 0.25f);
}

TEST(TextureFile, ErrorsNameTheFile) {
    const auto garbage = write_bytes("garbage.png", "this is not an image at all");
    try {
        load_texture_image(garbage);
        FAIL() << "loaded garbage";
    } catch (const ImageError& e) {
        EXPECT_EQ(e.file, garbage);
        EXPECT_NE(std::string(e.what()).find("garbage.png"), std::string::npos);
    }
    const auto missing = kOut / "missing.png";
    try {
        load_texture_image(missing);
        FAIL() << "loaded a missing file";
    } catch (const ImageError& e) {
        EXPECT_NE(std::string(e.what()).find("missing.png"), std::string::npos);
    }
}

TEST(TextureFile, HugeClaimedSizeIsRefusedBeforeDecoding) {
    // A BMP header claiming 100000 x 100000 pixels, with no pixel data.
    std::string bmp = "BM";
    const auto u32 = [](std::uint32_t v) {
        return std::string{char(v & 255), char((v >> 8) & 255), char((v >> 16) & 255),
                           char((v >> 24) & 255)};
    };
    const auto u16 = [](std::uint16_t v) { return std::string{char(v & 255), char(v >> 8)}; };
    bmp += u32(54) + u32(0) + u32(54);  // file size, reserved, data offset
    bmp += u32(40) + u32(100000) + u32(100000) + u16(1) + u16(24);  // info header
    bmp += u32(0) + u32(0) + u32(0) + u32(0) + u32(0) + u32(0);
    const auto path = write_bytes("huge.bmp", bmp);
    try {
        load_texture_image(path);
        FAIL() << "accepted a huge image";
    } catch (const ImageError& e) {
        EXPECT_NE(std::string(e.what()).find("huge.bmp"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace glint
