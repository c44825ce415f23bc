// Loading texture images: stb_image's formats sRGB-decoded or, for HDR, kept linear; OpenEXR and
// PFM as glint writes them; values no texture can hold refused; errors naming the file.
#include "glint/image/texture_file.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>
#include <vector>

#include "glint/image/image_error.h"
#include "glint/image/image_io.h"
#include "glint/image/srgb.h"

// stb's writer, for files of every texture format that glint did not write itself.
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>

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

// Every format, written by another library (stb_image_write), loads whole, and refused as
// truncated when cut in half: the check for data that ends early must catch every decoder and
// refuse no good file, whichever way it reads (TGA with and without run-length encoding,
// baseline JPEG, Radiance HDR's run-length scanlines).
TEST(TextureFile, EveryFormatLoadsWholeAndIsRefusedTruncated) {
    constexpr int kWidth = 37, kHeight = 23;  // odd sizes: no format's blocks fit exactly
    std::vector<unsigned char> bytes;
    std::vector<float> linear;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            for (const int v : {x * 255 / (kWidth - 1), y * 255 / (kHeight - 1), 128}) {
                bytes.push_back(static_cast<unsigned char>(v));
                linear.push_back(srgb_to_linear(float(v) / 255));
            }
        }
    }
    const auto append = [](void* file, void* data, int size) {
        static_cast<std::string*>(file)->append(static_cast<const char*>(data), size);
    };
    const auto* rgb = bytes.data();
    struct Format {
        std::string name;
        double tolerance;
        std::function<int(std::string*)> write;
    };
    const Format formats[] = {
        {"a.png", 1e-6,
         [&](std::string* f) {
             return stbi_write_png_to_func(append, f, kWidth, kHeight, 3, rgb, 0);
         }},
        {"a.bmp", 1e-6,
         [&](std::string* f) {
             return stbi_write_bmp_to_func(append, f, kWidth, kHeight, 3, rgb);
         }},
        {"raw.tga", 1e-6,
         [&](std::string* f) {
             stbi_write_tga_with_rle = 0;
             return stbi_write_tga_to_func(append, f, kWidth, kHeight, 3, rgb);
         }},
        {"rle.tga", 1e-6,
         [&](std::string* f) {
             stbi_write_tga_with_rle = 1;
             return stbi_write_tga_to_func(append, f, kWidth, kHeight, 3, rgb);
         }},
        {"a.jpg", 0.05,  // lossy
         [&](std::string* f) {
             return stbi_write_jpg_to_func(append, f, kWidth, kHeight, 3, rgb, 95);
         }},
        {"a.hdr", 0.01,  // RGBE: 8 bits of mantissa
         [&](std::string* f) {
             return stbi_write_hdr_to_func(append, f, kWidth, kHeight, 3, linear.data());
         }},
    };
    for (const Format& format : formats) {
        SCOPED_TRACE(format.name);
        std::string file;
        ASSERT_NE(format.write(&file), 0);
        const Image image = load_texture_image(write_bytes(format.name, file));
        ASSERT_EQ(image.width, kWidth);
        ASSERT_EQ(image.height, kHeight);
        double worst = 0;
        for (std::size_t i = 0; i < image.pixels.size(); ++i) {
            const Color c = image.pixels[i];
            worst = std::max({worst, std::abs(double(c.r) - linear[3 * i]),
                              std::abs(double(c.g) - linear[3 * i + 1]),
                              std::abs(double(c.b) - linear[3 * i + 2])});
        }
        EXPECT_LE(worst, format.tolerance);

        const auto half = write_bytes("half-" + format.name, file.substr(0, file.size() / 2));
        try {
            load_texture_image(half);
            ADD_FAILURE() << "half a file loaded";
        } catch (const ImageError& e) {
            EXPECT_NE(std::string(e.what()).find("truncated"), std::string::npos) << e.what();
        }
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

TEST(TextureFile, PngWhoseFirstDataChunkIsEmptyLoads) {
    // Empty IDAT chunks are allowed; stb's decoder passed a null pointer to memcpy for a first
    // one (found by fuzzing, under UBSan), so glint drops them before decoding.
    Image image(2, 1);
    image.at(0, 0) = {1, 1, 1};
    const auto path = kOut / "written.png";
    std::filesystem::create_directories(kOut);
    write_image(path, image);
    std::ifstream in(path, std::ios::binary);
    std::string png((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::size_t first_data = png.find("IDAT") - 4;  // the chunk starts with its length
    png.insert(first_data, std::string("\0\0\0\0IDAT\x35\xAF\x06\x1E", 12));  // CRC of "IDAT"
    const Image back = load_texture_image(write_bytes("empty-first-idat.png", png));
    ASSERT_EQ(back.width, 2);
    EXPECT_EQ(back.at(0, 0).r, 1);
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

TEST(TextureFile, ExrAndPfmLoadAsTheyWereWritten) {
    Image image(3, 2);
    for (int i = 0; i < 6; ++i) image.pixels[std::size_t(i)] = {0.1f * i, 2.5f * i, 1e3f * i};
    std::filesystem::create_directories(kOut);
    for (const char* name : {"floats.exr", "floats.pfm"}) {
        write_image(kOut / name, image);
        const Image read = load_texture_image(kOut / name);
        ASSERT_EQ(read.width, 3) << name;
        ASSERT_EQ(read.height, 2) << name;
        for (int i = 0; i < 6; ++i) {
            EXPECT_EQ(read.pixels[std::size_t(i)].r, image.pixels[std::size_t(i)].r) << name;
            EXPECT_EQ(read.pixels[std::size_t(i)].b, image.pixels[std::size_t(i)].b) << name;
        }
    }
    EXPECT_THROW(load_texture_image(kOut / "floats.exr", kMaxTextureFileBytes, 5), ImageError);
}

TEST(TextureFile, ValuesNoTextureCanHoldAreRefusedAtTheirPixel) {
    const float bad[] = {std::nanf(""), -1.0f, INFINITY};
    for (const float v : bad) {
        Image image(2, 2, Color::gray(0.5f));
        image.at(1, 0).g = v;
        // PFM writes every float as it is.
        std::filesystem::create_directories(kOut);
        const auto path = kOut / "bad-value.pfm";
        write_image(path, image);
        try {
            load_texture_image(path);
            FAIL() << "loaded a pixel of " << v;
        } catch (const ImageError& e) {
            EXPECT_NE(std::string(e.what()).find("pixel (1, 0)"), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("finite and >= 0"), std::string::npos);
        }
    }
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

// The bits per pixel sit at another offset in the old 12-byte BMP header (16-bit sides): the
// size check reads them there, so a whole file loads and one claiming more than it holds does not.
TEST(TextureFile, OldHeaderBmpIsCheckedAtItsOwnOffsets) {
    const auto u32 = [](std::uint32_t v) {
        return std::string{char(v & 255), char((v >> 8) & 255), char((v >> 16) & 255),
                           char((v >> 24) & 255)};
    };
    const auto u16 = [](std::uint16_t v) { return std::string{char(v & 255), char(v >> 8)}; };
    const auto bmp = [&](std::uint16_t side, const std::string& pixels) {
        return "BM" + u32(std::uint32_t(26 + pixels.size())) + u32(0) + u32(26) + u32(12) +
               u16(side) + u16(side) + u16(1) + u16(24) + pixels;
    };
    // 2 x 2, blue-green-red, rows padded to 4 bytes: white and black, then black and white.
    const std::string rows =
        std::string("\xff\xff\xff\0\0\0\0\0", 8) + std::string("\0\0\0\xff\xff\xff\0\0", 8);
    const Image image = load_texture_image(write_bytes("old.bmp", bmp(2, rows)));
    ASSERT_EQ(image.width, 2);
    EXPECT_FLOAT_EQ(image.at(0, 1).r, 1.0f);
    EXPECT_FLOAT_EQ(image.at(1, 1).r, 0.0f);
    try {
        load_texture_image(write_bytes("old-huge.bmp", bmp(5000, rows)));
        FAIL() << "decoded 5000 x 5000 pixels from 16 bytes";
    } catch (const ImageError& e) {
        EXPECT_NE(std::string(e.what()).find("truncated"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace glint
