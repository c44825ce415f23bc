// Bounds on image sizes, checked before any pixel memory is taken: a hostile or corrupt header
// must not be able to ask for terabytes (DESIGN principle 4).
#pragma once

#include <cstdint>
#include <filesystem>

#include "glint/image/image.h"

namespace glint {

inline constexpr std::int64_t kMaxImageDimension = std::int64_t(1) << 20;
// The default limit of the pixels of an image read, or of a render a scene asks for (raised by
// --max-pixels): 16384 x 16384, 3 GiB of float RGB.
inline constexpr std::int64_t kMaxImagePixels = std::int64_t(1) << 28;
// The most pixels glint makes an image of or writes: 65536 x 65536, its largest render.
inline constexpr std::int64_t kMaxWrittenImagePixels = std::int64_t(1) << 32;

// Throws ImageError naming `file` unless 0 < width, height <= kMaxImageDimension and
// width * height <= max_pixels. Readers call it with the sizes a header claims.
void check_image_size(const std::filesystem::path& file, std::int64_t width, std::int64_t height,
                      std::int64_t max_pixels = kMaxImagePixels);

// Throws ImageError naming `file` unless `image` has a valid size (up to kMaxWrittenImagePixels)
// and exactly width * height pixels. Writers call it so a malformed Image is an error, not an
// out-of-bounds read.
void check_image_shape(const std::filesystem::path& file, const Image& image);

}  // namespace glint
