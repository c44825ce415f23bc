// Extension-to-format table; the one place a new format's extension is registered.
#include "glint/image/image_format.h"

#include <array>
#include <cctype>
#include <string>
#include <utility>

namespace glint {
namespace {

constexpr std::array<std::pair<std::string_view, ImageFormat>, 4> kFormats{{
    {".png", ImageFormat::png},
    {".ppm", ImageFormat::ppm},
    {".pfm", ImageFormat::pfm},
    {".exr", ImageFormat::exr},
}};

}  // namespace

std::optional<ImageFormat> format_from_extension(const std::filesystem::path& path) {
    std::string extension = path.extension().string();
    for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
    for (const auto& [name, format] : kFormats) {
        if (extension == name) return format;
    }
    return std::nullopt;
}

std::string_view extension_of(ImageFormat format) {
    for (const auto& [name, f] : kFormats) {
        if (f == format) return name;
    }
    return {};
}

std::string_view known_image_extensions() {
    static const std::string text = [] {
        std::string list;
        for (const auto& entry : kFormats)
            list += (list.empty() ? "" : ", ") + std::string(entry.first);
        return list;
    }();
    return text;
}

}  // namespace glint
