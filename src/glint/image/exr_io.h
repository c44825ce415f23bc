// OpenEXR files: linear float RGB, the format for HDR output and for exact golden images.
#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "glint/image/image.h"

namespace glint {

// A layer written beside the image: channels "<name>.<channel>" taken from the image's r, g and b
// in turn (so one to three of them), e.g. "depth.Z", or "normal.X", "normal.Y", "normal.Z".
struct ExrLayer {
    std::string name;
    std::vector<std::string> channels;
    const Image* image;  // of the image's size
};

// Writes channels R, G, B, and those of each layer, as 32-bit floats with lossless ZIP
// compression, so the file holds the image bit for bit. Writes `path` directly; write_image()
// goes through a temporary. Throws ImageError.
void write_exr(const std::filesystem::path& path, const Image& image,
               std::span<const ExrLayer> layers = {});

// The bytes write_exr writes, in memory: for a page to download.
std::string exr_bytes(const Image& image, std::span<const ExrLayer> layers = {});

// Reads the R, G and B channels (half, float or uint) of the first part, scanline or tiled, over
// its data window; a missing channel reads as 0. Errors throw ImageError naming the file.
Image read_exr(const std::filesystem::path& path);

}  // namespace glint
