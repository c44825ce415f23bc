// Damage in texture data that stb_image (2.27, Debian 12's) mishandles instead of refusing,
// found before it decodes: each check walks the data as stb's decoder would.
#pragma once

#include <optional>
#include <span>
#include <string>

namespace glint {

inline constexpr const char* kTruncatedTexture =
    "the image data ends early (the file is truncated)";

// Why stb_image's Radiance HDR decoder would loop forever on `bytes`, if it would: its
// run-length scanlines never advance past a count of zero, and past the end of the data it reads
// zeros.
std::optional<std::string> hdr_hang(std::span<const unsigned char> bytes, int width, int height);

// Whether a TGA file (whatever stb_image does not take for another format) is too short for the
// size its header claims: stb decodes every pixel of it, past the end of the data too, which for
// a tiny file claiming millions of pixels takes seconds before glint can refuse it as truncated.
// A run-length packet holds at most 128 pixels.
bool tga_too_short(std::span<const unsigned char> bytes, int width, int height);

// Why stb_image's JPEG decoder would write out of bounds on `bytes`, if it would: it sizes a
// Huffman table's codes by the table's 16 counts without checking that they add up to at most
// 256, the size of its arrays (stb 2.28 checks).
std::optional<std::string> jpeg_overflow(std::span<const unsigned char> bytes);

}  // namespace glint
