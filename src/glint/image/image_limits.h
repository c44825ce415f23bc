// Bounds on image sizes, checked before any pixel memory is taken: a hostile or corrupt header
// must not be able to ask for terabytes (DESIGN principle 4).
#pragma once

#include <cstdint>
#include <filesystem>

#include "glint/image/image.h"

namespace glint {

inline constexpr std::int64_t kMaxImageDimension = std::int64_t(1) << 20;
inline constexpr std::int64_t kMaxImagePixels = std::int64_t(1) << 28;  // 3 GiB of float RGB

// Throws ImageError naming `file` unless 0 < width, height <= kMaxImageDimension and
// width * height <= kMaxImagePixels. Readers call it with the sizes a header claims.
void check_image_size(const std::filesystem::path& file, std::int64_t width, std::int64_t height);

// Throws ImageError naming `file` unless `image` has a valid size and exactly width * height
// pixels. Writers call it so a malformed Image is an error, not an out-of-bounds read.
void check_image_shape(const std::filesystem::path& file, const Image& image);

}  // namespace glint
