// The letters of a string in a TrueType (or OpenType) font as prism outlines, laid out as
// POV-Ray lays out its text object: glyphs in the x-y plane with the baseline on y = 0, one em
// high (font units over units-per-em), the first glyph's left edge at x = 0, each next one
// placed by the advance widths, left side bearings and kerning pairs of the font, and moved by
// `offset` more per letter (its x and y: POV-Ray leaves z out). The font is read with FreeType.
#pragma once

#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "glint/geometry/prism.h"
#include "glint/math/vector.h"

namespace glint {

struct TextOutlines {
    // Each letter's outlines in the x-y plane as (x, y), placed; a letter without outlines (a
    // space) has no entry.
    std::vector<std::vector<Outline>> glyphs;
    std::vector<std::string> missing;  // characters the font has no glyph for, as UTF-8
};

// The glyphs of `text` (UTF-8; a byte that is no UTF-8 counts as Latin-1) in the font held in
// `font`, whose name `font_name` errors name. Curves are cut within 1e-4 em. An error when the
// font cannot be read.
std::variant<TextOutlines, std::string> text_outlines(std::string_view font,
                                                      std::string_view font_name,
                                                      std::string_view text, Vector3 offset);

}  // namespace glint
