// PNG files through libpng (and libdeflate, which compresses the output): 8-bit sRGB output
// (dithered), and input of any standard PNG.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "glint/image/image.h"

namespace glint {

// Writes 8-bit RGB, sRGB-encoded and dithered (see quantize.h), with sRGB, gAMA and cHRM
// chunks. Writes `path` directly; write_image() goes through a temporary. Throws ImageError.
void write_png(const std::filesystem::path& path, const Image& image);

// How hard png_bytes compresses: as write_png does (libdeflate's fastest level), or not at all (the
// pixels stored as they are, a file two to four times as large made in about half the time: for
// a picture shown once on this machine and thrown away, a page's frame of a render in flight).
enum class PngDeflate { fast, stored };

// The bytes write_png writes, in memory: for a page that shows the image as it renders.
std::string png_bytes(const Image& image, PngDeflate deflate = PngDeflate::fast);

// Reads 1- to 16-bit gray, RGB and palette PNGs, with or without alpha, into linear floats.
// The samples are taken as sRGB-encoded whatever gAMA or iCCP chunks say, and alpha is
// dropped. A missing, truncated or corrupt file throws ImageError naming it.
Image read_png(const std::filesystem::path& path);

// A palette PNG's pixels as their palette indices (row by row from the top), for readers that
// take the index as a number (POV-Ray's height fields); nothing for a PNG without a palette or
// bytes that are no PNG. A malformed palette PNG throws ImageError naming `name`.
struct PaletteImage {
    int width = 0, height = 0;
    std::vector<std::uint8_t> indices;
};
std::optional<PaletteImage> read_png_palette(std::span<const unsigned char> bytes,
                                             const std::filesystem::path& name);

}  // namespace glint
