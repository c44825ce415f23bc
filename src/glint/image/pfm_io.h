// PFM (portable float map) files: linear float RGB with no loss, the simplest HDR format.
#pragma once

#include <filesystem>

#include "glint/image/image.h"

namespace glint {

// Writes "PF" colour, little-endian (scale -1), rows bottom to top as the format requires; the
// floats are stored bit for bit, NaN and infinity included. Writes `path` directly;
// write_image() goes through a temporary. Throws ImageError.
void write_pfm(const std::filesystem::path& path, const Image& image);

// Reads "PF" colour and "Pf" grayscale, either byte order (by the scale's sign). The scale's
// magnitude is ignored, as most tools do. Malformed files throw ImageError naming the file.
Image read_pfm(const std::filesystem::path& path);

}  // namespace glint
