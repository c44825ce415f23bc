// Linear colours to 8-bit sRGB for PNG and PPM output, dithered so smooth gradients do not band.
// The dither is a fixed hash of (x, y, channel): the same image always gives the same bytes.
#pragma once

#include <cstdint>
#include <vector>

#include "glint/image/image.h"

namespace glint {

// One channel value: clamped to [0, 1] (NaN becomes 0), sRGB-encoded, then rounded to 8 bits
// after adding noise uniform in [-0.5, 0.5) LSB, so the expected byte equals the encoded value.
std::uint8_t quantize_srgb8(float linear, int x, int y, int channel);

// Row y of the image as RGB bytes, 3 * width of them from `out`: the values quantize_srgb8 gives
// one at a time, several times as fast.
void quantize_srgb8_row(const Image& image, int y, std::uint8_t* out);

// The whole image as RGB bytes, rows from the top.
std::vector<std::uint8_t> quantize_srgb8(const Image& image);

}  // namespace glint
