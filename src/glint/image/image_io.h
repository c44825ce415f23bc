// Reading and writing images by file name: the extension picks the format (.png, .ppm, .pfm,
// .exr, any case), and every write goes through a temporary file renamed into place.
#pragma once

#include <filesystem>
#include <span>

#include "glint/image/exr_io.h"
#include "glint/image/image.h"

namespace glint {

struct WriteOptions {
    bool ppm_ascii = false;  // .ppm as plain "P3" text instead of binary "P6"
    // Layers beside the image (output variables): .exr only, other formats throw ImageError.
    std::span<const ExrLayer> exr_layers;
};

// Throws ImageError naming `path` for an unknown extension, an image whose size is not
// positive or does not match its pixel count, or any write failure; on failure an existing
// file at `path` is left as it was.
void write_image(const std::filesystem::path& path, const Image& image,
                 const WriteOptions& options = {});

// Throws ImageError naming `path` for an unknown extension or an unreadable or malformed file.
Image read_image(const std::filesystem::path& path);

}  // namespace glint
