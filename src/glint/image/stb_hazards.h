// Damage in texture data that stb_image (2.27, Debian 12's) mishandles instead of refusing,
// found before it decodes: each check walks the data as stb's decoder would.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

namespace glint {

inline constexpr const char* kTruncatedTexture =
    "the image data ends early (the file is truncated)";

// Why stb_image's Radiance HDR decoder would loop forever on `bytes`, if it would: its
// run-length scanlines never advance past a count of zero, and past the end of the data it reads
// zeros.
std::optional<std::string> hdr_hang(std::span<const unsigned char> bytes, int width, int height);

// Whether the file is too short for the size its header claims, by the most pixels its format
// can pack into a byte: stb decodes every pixel, past the end of the data too, so a file of a
// few hundred bytes claiming hundreds of millions of pixels would take gigabytes and minutes
// before glint could refuse it as truncated. A PNG chunk longer than the rest of the file is
// truncation too.
bool too_short_for_size(std::span<const unsigned char> bytes, int width, int height);

// The PNG without its empty IDAT chunks, or nothing when it has none: stb's PNG decoder passes
// a null pointer to memcpy (undefined, though it copies nothing) for one that comes first.
std::vector<unsigned char> png_without_empty_data(std::span<const unsigned char> bytes);

// Why stb_image's JPEG decoder would write out of bounds on `bytes`, if it would: it sizes a
// Huffman table's codes by the table's 16 counts without checking that they add up to at most
// 256, the size of its arrays (stb 2.28 checks).
std::optional<std::string> jpeg_overflow(std::span<const unsigned char> bytes);

}  // namespace glint
