// The legends' font and colour maps: glyphs land where they should, clipped at the edges; viridis
// keeps its published ends and grows lighter; ids get colours apart from their neighbours'.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "glint/image/bitmap_font.h"
#include "glint/image/colour_map.h"
#include "glint/image/srgb.h"

namespace glint {
namespace {

int lit(const Image& image) {
    int n = 0;
    for (const Color& c : image.pixels) n += c.r > 0;
    return n;
}

TEST(BitmapFont, DrawsEachGlyphsPixels) {
    Image image(20, 10);
    draw_text(image, 1, 1, "1", Color::gray(1));
    EXPECT_EQ(lit(image), 10);       // ..#.. .##.. ..#.. x4 .###.
    EXPECT_EQ(image.at(3, 1).r, 1);  // the top of the stem, column 2
    EXPECT_EQ(image.at(1, 1).r, 0);
    Image doubled(20, 20);
    draw_text(doubled, 0, 0, "1", Color::gray(1), 2);
    EXPECT_EQ(lit(doubled), 40);
}

TEST(BitmapFont, CapitalsAreSmallLettersAndUnknownCharactersBlank) {
    Image upper(12, 8), lower(12, 8), unknown(12, 8);
    draw_text(upper, 0, 0, "A", Color::gray(1));
    draw_text(lower, 0, 0, "a", Color::gray(1));
    draw_text(unknown, 0, 0, "#", Color::gray(1));
    EXPECT_EQ(upper.pixels, lower.pixels);
    EXPECT_GT(lit(lower), 0);
    EXPECT_EQ(lit(unknown), 0);
    EXPECT_EQ(text_width("ab", 1), 11);
    EXPECT_EQ(text_width("ab", 2), 22);
    EXPECT_EQ(text_width("", 2), 0);
}

TEST(BitmapFont, TextIsClippedToTheImage) {
    Image image(4, 4);
    draw_text(image, -3, -3, "0123456789 abc", Color::gray(1), 3);  // must not write outside
    draw_text(image, 2, 2, "88", Color::gray(1));
    EXPECT_GT(lit(image), 0);
}

TEST(ColourMap, ViridisEndsAsPublishedAndGrowsLighter) {
    const auto srgb8 = [](Color c) {
        return std::array<int, 3>{int(linear_to_srgb(c.r) * 255 + 0.5f),
                                  int(linear_to_srgb(c.g) * 255 + 0.5f),
                                  int(linear_to_srgb(c.b) * 255 + 0.5f)};
    };
    EXPECT_EQ(srgb8(colour_map(0)), (std::array<int, 3>{68, 1, 84}));        // #440154
    EXPECT_EQ(srgb8(colour_map(0.5f)), (std::array<int, 3>{33, 145, 140}));  // #21918c
    EXPECT_EQ(srgb8(colour_map(1)), (std::array<int, 3>{253, 231, 37}));     // #fde725
    EXPECT_EQ(colour_map(-5), colour_map(0));
    EXPECT_EQ(colour_map(7), colour_map(1));
    float last = -1;
    for (int i = 0; i <= 32; ++i) {
        const Color c = colour_map(float(i) / 32);
        const float luminance = 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b;
        EXPECT_GT(luminance, last) << i;
        last = luminance;
    }
}

TEST(ColourMap, IdsGetColoursApartAndNothingIsBlack) {
    EXPECT_EQ(id_colour(-1), Color{});
    for (int id = 0; id < 64; ++id) {
        const Color a = id_colour(id), b = id_colour(id + 1);
        EXPECT_GT(std::abs(a.r - b.r) + std::abs(a.g - b.g) + std::abs(a.b - b.b), 0.05f) << id;
        EXPECT_GT(a.r + a.g + a.b, 0.05f) << id;
    }
}

}  // namespace
}  // namespace glint
