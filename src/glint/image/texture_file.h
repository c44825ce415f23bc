// Reading texture images (PNG, JPEG, Radiance HDR, TGA, BMP) with stb_image into linear RGB.
// 8- and 16-bit data are sRGB-decoded; HDR data is linear already. Alpha is dropped.
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>

#include "glint/image/image.h"

namespace glint {

// Larger texture files are refused before they are read (stb_image takes an int length).
inline constexpr std::uintmax_t kMaxTextureFileBytes = std::uintmax_t(1) << 30;

// Throws ImageError naming `path` when the file cannot be read, is too large, is not an image
// stb_image knows, or claims a size beyond check_image_size (checked before decoding).
Image load_texture_image(const std::filesystem::path& path);

// The same for an image already in memory (textures embedded in .glb files); `name` stands for
// the file in errors.
Image decode_texture_image(std::span<const unsigned char> bytes, const std::filesystem::path& name);

}  // namespace glint
