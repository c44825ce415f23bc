// The image file formats glint reads and writes, and how a file name selects one.
#pragma once

#include <filesystem>
#include <optional>
#include <string_view>

namespace glint {

enum class ImageFormat { png, ppm, pfm, exr };

// The format named by the path's extension, ignoring case (".PNG" is PNG); nothing if the
// extension is missing or unknown.
std::optional<ImageFormat> format_from_extension(const std::filesystem::path& path);

// The canonical extension with its dot, e.g. ".png".
std::string_view extension_of(ImageFormat format);

// ".png, .ppm, .pfm, .exr": for error messages that list the choices.
std::string_view known_image_extensions();

}  // namespace glint
