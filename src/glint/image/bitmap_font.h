// A 5x7 pixel font for the legends glint draws into images (the output variables' colour maps):
// digits, lower-case letters and a few signs, nothing to install.
#pragma once

#include <string_view>

#include "glint/image/image.h"

namespace glint {

inline constexpr int kGlyphWidth = 5, kGlyphHeight = 7;
inline constexpr int kGlyphAdvance = kGlyphWidth + 1;  // a column between characters

// Draws `text` with its top left corner at (x, y), each font pixel a square of `scale` image
// pixels, clipped to the image. Capitals are drawn as small letters; a character without a glyph
// leaves a blank.
void draw_text(Image& image, int x, int y, std::string_view text, Color colour, int scale = 1);

// The width draw_text takes for `text`, in image pixels.
inline int text_width(std::string_view text, int scale = 1) {
    return text.empty() ? 0 : (int(text.size()) * kGlyphAdvance - 1) * scale;
}

}  // namespace glint
