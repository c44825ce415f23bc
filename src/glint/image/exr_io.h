// OpenEXR files: linear float RGB, the format for HDR output and for exact golden images.
#pragma once

#include <filesystem>

#include "glint/image/image.h"

namespace glint {

// Writes channels R, G, B as 32-bit floats with lossless ZIP compression, so the file holds
// the image bit for bit. Writes `path` directly; write_image() goes through a temporary.
// Throws ImageError.
void write_exr(const std::filesystem::path& path, const Image& image);

// Reads the R, G and B channels (half, float or uint) of the first part, scanline or tiled, over
// its data window; a missing channel reads as 0. Errors throw ImageError naming the file.
Image read_exr(const std::filesystem::path& path);

}  // namespace glint
