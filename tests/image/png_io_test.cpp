#include "glint/image/png_io.h"

#include <gtest/gtest.h>
#include <png.h>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "glint/image/image_error.h"
#include "glint/image/srgb.h"
#include "test_files.h"

namespace glint {
namespace {

Image random_image(int width, int height, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> value(0, 1);
    Image image(width, height);
    for (Color& c : image.pixels) c = {value(rng), value(rng), value(rng)};
    return image;
}

// Writes a PNG of any layout with libpng's simplified API (which needs no setjmp).
void write_simple_png(const std::filesystem::path& path, png_uint_32 format, int width, int height,
                      const void* buffer, const void* colormap = nullptr,
                      int colormap_entries = 0) {
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    image.width = png_uint_32(width);
    image.height = png_uint_32(height);
    image.format = format;
    image.colormap_entries = png_uint_32(colormap_entries);
    ASSERT_NE(png_image_write_to_file(&image, path.c_str(), 0, buffer, 0, colormap), 0)
        << image.message;
}

int bit_depth_of(const std::string& png) { return png.at(24); }  // IHDR fields
int color_type_of(const std::string& png) { return png.at(25); }

void expect_color_near(Color actual, Color expected, float tolerance = 1e-6f) {
    EXPECT_NEAR(actual.r, expected.r, tolerance);
    EXPECT_NEAR(actual.g, expected.g, tolerance);
    EXPECT_NEAR(actual.b, expected.b, tolerance);
}

float from8(int v) { return srgb_to_linear(float(v) / 255); }
float from16(int v) { return srgb_to_linear(float(v) / 65535); }

TEST(Png, RoundTripIsWithinOneLevelInSrgb) {
    const auto path = testing::fresh_test_dir() / "round_trip.png";
    const Image image = random_image(37, 23, 1);
    write_png(path, image);
    const Image back = read_png(path);
    ASSERT_EQ(back.width, 37);
    ASSERT_EQ(back.height, 23);
    for (std::size_t i = 0; i < image.pixels.size(); ++i) {
        const Color a = image.pixels[i], b = back.pixels[i];
        EXPECT_LT(std::abs(linear_to_srgb(a.r) - linear_to_srgb(b.r)), 1.0f / 255 + 1e-6f);
        EXPECT_LT(std::abs(linear_to_srgb(a.g) - linear_to_srgb(b.g)), 1.0f / 255 + 1e-6f);
        EXPECT_LT(std::abs(linear_to_srgb(a.b) - linear_to_srgb(b.b)), 1.0f / 255 + 1e-6f);
    }
}

TEST(Png, BytesInMemoryAreTheFilesBytes) {
    const auto dir = testing::fresh_test_dir();
    const Image image = random_image(41, 17, 5);
    write_png(dir / "file.png", image);
    EXPECT_EQ(png_bytes(image), testing::read_file(dir / "file.png"));
    EXPECT_THROW(png_bytes(Image(0, 3)), ImageError);
}

TEST(Png, StoredBytesHoldTheSamePixelsUncompressed) {
    const auto dir = testing::fresh_test_dir();
    const Image image = random_image(64, 32, 6);
    const std::string stored = png_bytes(image, PngDeflate::stored);
    // Each row's filter byte and three bytes a pixel, in deflate's stored blocks, and the chunks.
    EXPECT_GT(stored.size(), std::size_t(32 * (1 + 64 * 3)));
    EXPECT_LT(stored.size(), std::size_t(32 * (1 + 64 * 3)) + 200);
    std::ofstream(dir / "stored.png", std::ios::binary) << stored;
    write_png(dir / "fast.png", image);
    EXPECT_EQ(read_png(dir / "stored.png").pixels, read_png(dir / "fast.png").pixels);
}

// The compressed pixels go in IDAT chunks of at most 1 MiB: an image larger than that is split,
// and reads back whole.
TEST(Png, ImageDataOverManyChunksReadsBackWhole) {
    const auto dir = testing::fresh_test_dir();
    const Image image = random_image(800, 600, 9);  // 1.4 MB of scanlines, stored
    const std::string stored = png_bytes(image, PngDeflate::stored);
    std::size_t chunks = 0;
    for (std::size_t at = stored.find("IDAT"); at != std::string::npos;
         at = stored.find("IDAT", at + 4))
        ++chunks;
    EXPECT_EQ(chunks, 2u);
    std::ofstream(dir / "stored.png", std::ios::binary) << stored;
    write_png(dir / "fast.png", image);
    const Image back = read_png(dir / "stored.png");
    EXPECT_EQ(back.width, 800);
    EXPECT_EQ(back.pixels, read_png(dir / "fast.png").pixels);
}

TEST(Png, SameImageGivesSameBytesAndReadingBackRewritesThemExactly) {
    const auto dir = testing::fresh_test_dir();
    const Image image = random_image(40, 30, 2);
    write_png(dir / "a.png", image);
    write_png(dir / "b.png", image);
    const std::string bytes = testing::read_file(dir / "a.png");
    EXPECT_EQ(bytes, testing::read_file(dir / "b.png"));
    write_png(dir / "c.png", read_png(dir / "a.png"));
    EXPECT_EQ(bytes, testing::read_file(dir / "c.png"));
}

TEST(Png, WritesEightBitRgbWithAnSrgbChunk) {
    const auto path = testing::fresh_test_dir() / "layout.png";
    write_png(path, Image(3, 2, Color::gray(0.5f)));
    const std::string bytes = testing::read_file(path);
    EXPECT_EQ(bit_depth_of(bytes), 8);
    EXPECT_EQ(color_type_of(bytes), 2);  // RGB
    EXPECT_NE(bytes.find("sRGB"), std::string::npos);
}

TEST(Png, ClampsOutOfRangeValuesAndWritesNanAsZero) {
    const auto path = testing::fresh_test_dir() / "clamp.png";
    write_png(path, Image(1, 1, Color(5, -1, std::numeric_limits<float>::quiet_NaN())));
    EXPECT_EQ(read_png(path).at(0, 0), Color(1, 0, 0));
}

TEST(Png, ReadsEightBitGray) {
    const auto path = testing::fresh_test_dir() / "gray8.png";
    const std::uint8_t gray[] = {0, 128, 255, 7};
    write_simple_png(path, PNG_FORMAT_GRAY, 2, 2, gray);
    ASSERT_EQ(color_type_of(testing::read_file(path)), 0);
    const Image image = read_png(path);
    ASSERT_EQ(image.width, 2);
    ASSERT_EQ(image.height, 2);
    EXPECT_EQ(image.at(0, 0), Color::gray(0));
    expect_color_near(image.at(1, 0), Color::gray(from8(128)));
    EXPECT_EQ(image.at(0, 1), Color::gray(1));
    expect_color_near(image.at(1, 1), Color::gray(from8(7)));
}

TEST(Png, ReadsSixteenBitGrayAndRgb) {
    const auto dir = testing::fresh_test_dir();
    const std::uint16_t gray[] = {0, 1000, 65535};
    write_simple_png(dir / "gray16.png", PNG_FORMAT_LINEAR_Y, 3, 1, gray);
    ASSERT_EQ(bit_depth_of(testing::read_file(dir / "gray16.png")), 16);
    const Image g = read_png(dir / "gray16.png");
    expect_color_near(g.at(1, 0), Color::gray(from16(1000)));
    EXPECT_EQ(g.at(2, 0), Color::gray(1));

    const std::uint16_t rgb[] = {65535, 30000, 1, 2, 40000, 65000};
    write_simple_png(dir / "rgb16.png", PNG_FORMAT_LINEAR_RGB, 2, 1, rgb);
    ASSERT_EQ(bit_depth_of(testing::read_file(dir / "rgb16.png")), 16);
    const Image c = read_png(dir / "rgb16.png");
    expect_color_near(c.at(0, 0), Color(1, from16(30000), from16(1)));
    expect_color_near(c.at(1, 0), Color(from16(2), from16(40000), from16(65000)));
}

TEST(Png, ReadsATwoBitPalette) {
    const auto path = testing::fresh_test_dir() / "palette.png";
    const std::uint8_t colormap[] = {255, 0, 0, 0, 255, 0, 0, 0, 255, 10, 20, 30};
    const std::uint8_t indices[] = {0, 1, 2, 3, 3, 2};
    write_simple_png(path, PNG_FORMAT_RGB_COLORMAP, 3, 2, indices, colormap, 4);
    const std::string bytes = testing::read_file(path);
    ASSERT_EQ(color_type_of(bytes), 3);
    ASSERT_EQ(bit_depth_of(bytes), 2);
    const Image image = read_png(path);
    EXPECT_EQ(image.at(0, 0), Color(1, 0, 0));
    EXPECT_EQ(image.at(1, 0), Color(0, 1, 0));
    EXPECT_EQ(image.at(2, 0), Color(0, 0, 1));
    expect_color_near(image.at(0, 1), Color(from8(10), from8(20), from8(30)));
    EXPECT_EQ(image.at(2, 1), Color(0, 0, 1));
}

TEST(Png, DropsAlpha) {
    const auto path = testing::fresh_test_dir() / "rgba.png";
    const std::uint8_t rgba[] = {255, 128, 0, 0, 1, 2, 3, 200};
    write_simple_png(path, PNG_FORMAT_RGBA, 2, 1, rgba);
    const Image image = read_png(path);
    expect_color_near(image.at(0, 0), Color(1, from8(128), 0));
    expect_color_near(image.at(1, 0), Color(from8(1), from8(2), from8(3)));
}

TEST(Png, ReadsInterlacedFiles) {
    const auto path = testing::fresh_test_dir() / "interlaced.png";
    constexpr int kWidth = 9, kHeight = 7;
    std::vector<png_byte> pixels(kWidth * kHeight * 3);
    for (std::size_t i = 0; i < pixels.size(); ++i) pixels[i] = png_byte(i * 7);
    std::vector<png_bytep> rows(kHeight);
    for (int y = 0; y < kHeight; ++y) rows[y] = pixels.data() + y * kWidth * 3;
    {
        // The simplified API cannot interlace; libpng's default error handler aborts, which is
        // fine for a test that only writes a known-good file.
        std::FILE* file = std::fopen(path.c_str(), "wb");
        ASSERT_NE(file, nullptr);
        png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
        png_infop info = png_create_info_struct(png);
        png_init_io(png, file);
        png_set_IHDR(png, info, kWidth, kHeight, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_ADAM7,
                     PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
        png_write_info(png, info);
        png_write_image(png, rows.data());
        png_write_end(png, info);
        png_destroy_write_struct(&png, &info);
        std::fclose(file);
    }
    const Image image = read_png(path);
    ASSERT_EQ(image.width, kWidth);
    ASSERT_EQ(image.height, kHeight);
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            const png_byte* p = rows[y] + 3 * x;
            ASSERT_EQ(image.at(x, y), Color(from8(p[0]), from8(p[1]), from8(p[2])));
        }
    }
}

TEST(Png, MissingGarbageTruncatedAndCorruptFilesAreErrors) {
    const auto dir = testing::fresh_test_dir();
    testing::expect_image_error([&] { read_png(dir / "missing.png"); }, dir / "missing.png",
                                "cannot open for reading");

    testing::write_file(dir / "garbage.png", "this is not a PNG at all");
    testing::expect_image_error([&] { read_png(dir / "garbage.png"); }, dir / "garbage.png",
                                "not a PNG file");
    testing::write_file(dir / "empty.png", "");
    testing::expect_image_error([&] { read_png(dir / "empty.png"); }, dir / "empty.png",
                                "not a PNG file");

    write_png(dir / "good.png", random_image(32, 32, 3));
    const std::string good = testing::read_file(dir / "good.png");
    testing::write_file(dir / "truncated.png", good.substr(0, good.size() / 2));
    testing::expect_image_error([&] { read_png(dir / "truncated.png"); }, dir / "truncated.png",
                                "malformed PNG");
    testing::write_file(dir / "header_only.png", good.substr(0, 20));
    testing::expect_image_error([&] { read_png(dir / "header_only.png"); }, dir / "header_only.png",
                                "malformed PNG");

    std::string corrupt = good;
    corrupt[corrupt.size() / 2] ^= 0x55;  // inside IDAT: the CRC no longer matches
    testing::write_file(dir / "corrupt.png", corrupt);
    testing::expect_image_error([&] { read_png(dir / "corrupt.png"); }, dir / "corrupt.png",
                                "malformed PNG");
}

TEST(Png, DamagedFilesNeverCrash) {
    const auto dir = testing::fresh_test_dir();
    write_png(dir / "good.png", random_image(24, 16, 4));
    const std::string good = testing::read_file(dir / "good.png");
    const auto path = dir / "damaged.png";
    const auto read_or_image_error = [&](const std::string& bytes) {
        testing::write_file(path, bytes);
        try {
            read_png(path);
        } catch (const ImageError&) {
        }
    };
    for (std::size_t length = 0; length < good.size(); length += 5) {
        read_or_image_error(good.substr(0, length));
    }
    std::mt19937 rng(5);
    for (int trial = 0; trial < 300; ++trial) {
        std::string bytes = good;
        for (int flips = 0; flips < 1 + trial % 4; ++flips) {
            bytes[rng() % bytes.size()] = char(rng());
        }
        read_or_image_error(bytes);
    }
}

}  // namespace
}  // namespace glint
