// Reading texture images into linear RGB: PNG, JPEG, Radiance HDR, TGA and BMP with stb_image
// (8- and 16-bit data sRGB-decoded, HDR data linear already, alpha dropped), and OpenEXR and PFM
// (linear floats) as glint writes them.
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
// than max_bytes (or kMaxDecodableTextureBytes), is not an image it knows (by content; .exr and
// .pfm by name), claims more than max_pixels or a side beyond check_image_size (checked before
// decoding, but for .exr and .pfm against kMaxImagePixels), or holds a value that is not finite
// or is negative.
Image load_texture_image(const std::filesystem::path& path,
                         std::uintmax_t max_bytes = kMaxTextureFileBytes,
                         std::int64_t max_pixels = kMaxImagePixels);

// The same for an image already in memory (textures embedded in .glb files); `name` stands for
// the file in errors.
Image decode_texture_image(std::span<const unsigned char> bytes, const std::filesystem::path& name,
                           std::int64_t max_pixels = kMaxImagePixels);

// Throws ImageError naming `path` at the first pixel whose value is NaN, infinite or negative.
void check_texture_values(const std::filesystem::path& path, const Image& image);

}  // namespace glint
