// The layout of text against POV-Ray's: the extents below are what POV-Ray 3.7 prints for
// min_extent and max_extent of the same text objects in the same font (within its 1e-5 padding).
#include "glint/scene/font_outlines.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace glint {
namespace {

std::string font_bytes(const std::string& name) {
    std::ifstream in(std::filesystem::path(GLINT_SOURCE_DIR) / "tests/data/pov" / name,
                     std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
}

struct Extent {
    float min_x = 1e30f, min_y = 1e30f, max_x = -1e30f, max_y = -1e30f;
};

Extent extent_of(const TextOutlines& text) {
    Extent e;
    for (const auto& glyph : text.glyphs) {
        for (const Outline& outline : glyph) {
            for (const OutlineEdge& edge : outline) {
                for (const Point2 p : {edge.a, edge.b}) {
                    e.min_x = std::min(e.min_x, p.x);
                    e.min_y = std::min(e.min_y, p.y);
                    e.max_x = std::max(e.max_x, p.x);
                    e.max_y = std::max(e.max_y, p.y);
                }
            }
        }
    }
    return e;
}

TextOutlines laid_out(const std::string& text, Vector3 offset = {0, 0, 0}) {
    auto result = text_outlines(font_bytes("timrom.ttf"), "timrom.ttf", text, offset);
    EXPECT_TRUE(std::holds_alternative<TextOutlines>(result)) << std::get<std::string>(result);
    return std::get<TextOutlines>(result);
}

TEST(FontOutlines, LettersSitAsPovRayPlacesThem) {
    // text { ttf "timrom.ttf" "I" 1, 0 }: POV-Ray's extent <0, 0> to <0.296, 0.680>.
    Extent e = extent_of(laid_out("I"));
    EXPECT_NEAR(e.min_x, 0, 1e-6);
    EXPECT_NEAR(e.min_y, 0, 1e-4);
    EXPECT_NEAR(e.max_x, 0.296, 1e-4);
    EXPECT_NEAR(e.max_y, 0.680, 1e-4);
    // "AV" is kerned: 1.278 wide where "A" alone is 0.736 wide.
    e = extent_of(laid_out("AV"));
    EXPECT_NEAR(e.min_y, -0.016, 1e-4);
    EXPECT_NEAR(e.max_x, 1.278, 1e-4);
    EXPECT_NEAR(e.max_y, 0.696, 1e-4);
    EXPECT_NEAR(extent_of(laid_out("A")).max_x, 0.736, 1e-4);
    // text { ttf "timrom.ttf" "Glint" 0.5, <0.1, 0.05, 0> }: each letter 0.1 further right and
    // 0.05 higher than the advance puts it.
    e = extent_of(laid_out("Glint", {0.1f, 0.05f, 0}));
    EXPECT_NEAR(e.min_x, 0, 1e-4);
    EXPECT_NEAR(e.min_y, -0.016, 1e-4);
    EXPECT_NEAR(e.max_x, 2.489, 1e-4);
    EXPECT_NEAR(e.max_y, 0.817, 1e-4);
}

TEST(FontOutlines, LetterHolesAreOutlinesOfTheirOwnAndSpacesHaveNone) {
    const TextOutlines text = laid_out("o B");
    ASSERT_EQ(text.glyphs.size(), 2u);     // the space has no outline
    EXPECT_EQ(text.glyphs[0].size(), 2u);  // o: outside and the hole
    EXPECT_EQ(text.glyphs[1].size(), 3u);  // B: outside and two holes
    EXPECT_TRUE(text.missing.empty());
    // Every outline is closed: each edge starts where the one before ended, within the
    // rounding of a curve's end (which make_prism joins).
    for (const auto& glyph : text.glyphs) {
        for (const Outline& outline : glyph) {
            for (std::size_t i = 0; i < outline.size(); ++i) {
                const Point2 end = outline[(i + outline.size() - 1) % outline.size()].b;
                EXPECT_NEAR(outline[i].a.x, end.x, 1e-6f);
                EXPECT_NEAR(outline[i].a.y, end.y, 1e-6f);
            }
        }
    }
}

TEST(FontOutlines, MissingGlyphsAndBadFontsAreSaid) {
    const TextOutlines text = laid_out("A\xe2\x82\xac");  // "A€": timrom has no euro sign
    EXPECT_EQ(text.missing, std::vector<std::string>{"\xe2\x82\xac"});
    const auto bad = text_outlines("not a font", "notes.txt", "A", {0, 0, 0});
    EXPECT_EQ(std::get<std::string>(bad),
              "notes.txt is not a font FreeType reads (TrueType, OpenType)");
}

}  // namespace
}  // namespace glint
