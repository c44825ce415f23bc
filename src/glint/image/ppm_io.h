// PPM (Netpbm colour) files: 8-bit sRGB output like PNG's, and input of binary and ASCII PPMs.
#pragma once

#include <filesystem>

#include "glint/image/image.h"

namespace glint {

enum class PpmEncoding {
    binary,  // "P6": compact; what every viewer expects
    ascii,   // "P3": one pixel per line, readable and diffable in tests
};

// Writes maxval 255, sRGB-encoded and dithered exactly like write_png (see quantize.h).
// Writes `path` directly; write_image() goes through a temporary. Throws ImageError.
void write_ppm(const std::filesystem::path& path, const Image& image,
               PpmEncoding encoding = PpmEncoding::binary);

// Reads P3 and P6 with any maxval from 1 to 65535 and '#' comments in the header; samples are
// taken as sRGB-encoded. A malformed file throws ImageError naming it and what was wrong.
Image read_ppm(const std::filesystem::path& path);

}  // namespace glint
