// Reading texture images (PNG, JPEG, Radiance HDR, TGA, BMP) with stb_image into linear RGB.
// 8- and 16-bit data are sRGB-decoded; HDR data is linear already. Alpha is dropped.
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>

#include "glint/image/image.h"
#include "glint/image/image_limits.h"

namespace glint {

// Larger texture files are refused before they are read (stb_image takes an int length).
inline constexpr std::uintmax_t kMaxTextureFileBytes = std::uintmax_t(1) << 30;
// The decoder takes sizes as int: no limit raises a texture file past this.
inline constexpr std::uintmax_t kMaxDecodableTextureBytes = 0x7fffffff;

// Throws ImageError naming `path` when the file cannot be read, is not a regular file, is larger
// than max_bytes (or kMaxDecodableTextureBytes), is not an image stb_image knows, or claims more
// than max_pixels or a side beyond check_image_size (checked before decoding).
Image load_texture_image(const std::filesystem::path& path,
                         std::uintmax_t max_bytes = kMaxTextureFileBytes,
                         std::int64_t max_pixels = kMaxImagePixels);

// The same for an image already in memory (textures embedded in .glb files); `name` stands for
// the file in errors.
Image decode_texture_image(std::span<const unsigned char> bytes, const std::filesystem::path& name,
                           std::int64_t max_pixels = kMaxImagePixels);

}  // namespace glint
