// stb_image behind glint's Image: size checks first, then decoding, then sRGB to linear.
#include "glint/image/texture_file.h"

#include <array>
#include <climits>
#include <memory>
#include <system_error>

#include "glint/image/file_io.h"
#include "glint/image/image_error.h"
#include "glint/image/image_limits.h"
#include "glint/image/srgb.h"

// Only the formats glint documents; static so that nothing clashes with a libstb linked elsewhere.
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#define STBI_ONLY_JPEG
#define STBI_ONLY_HDR
#define STBI_ONLY_TGA
#define STBI_ONLY_BMP
#define STBI_NO_STDIO
#include <stb/stb_image.h>

namespace glint {

namespace {

struct StbFree {
    void operator()(void* p) const { stbi_image_free(p); }
};

std::string stb_reason() {
    const char* reason = stbi_failure_reason();
    return reason ? reason : "unknown error";
}

// Decoding 8-bit values through a table keeps the pow() calls to 256.
const std::array<float, 256>& srgb8_table() {
    static const std::array<float, 256> table = [] {
        std::array<float, 256> t{};
        for (int i = 0; i < 256; ++i) t[std::size_t(i)] = srgb_to_linear(float(i) / 255);
        return t;
    }();
    return table;
}

}  // namespace

Image decode_texture_image(std::span<const unsigned char> bytes,
                           const std::filesystem::path& name) {
    if (bytes.size() > kMaxTextureFileBytes || bytes.size() > std::size_t(INT_MAX)) {
        throw ImageError(name, "texture is larger than 1 GiB");
    }
    const auto* data = bytes.data();
    const int length = int(bytes.size());
    int width = 0, height = 0, channels = 0;
    if (!stbi_info_from_memory(data, length, &width, &height, &channels)) {
        throw ImageError(name, "not a PNG, JPEG, HDR, TGA or BMP image stb_image can read (" +
                                   stb_reason() + ")");
    }
    check_image_size(name, width, height);

    Image image(width, height);
    const std::size_t pixels = std::size_t(width) * std::size_t(height);
    int w = 0, h = 0, n = 0;
    if (stbi_is_hdr_from_memory(data, length)) {
        const std::unique_ptr<float, StbFree> decoded(
            stbi_loadf_from_memory(data, length, &w, &h, &n, 3));
        if (!decoded || w != width || h != height) {
            throw ImageError(name, "cannot decode HDR image: " + stb_reason());
        }
        for (std::size_t i = 0; i < pixels; ++i) {
            const float* p = decoded.get() + 3 * i;
            image.pixels[i] = {p[0], p[1], p[2]};
        }
    } else if (stbi_is_16_bit_from_memory(data, length)) {
        const std::unique_ptr<stbi_us, StbFree> decoded(
            stbi_load_16_from_memory(data, length, &w, &h, &n, 3));
        if (!decoded || w != width || h != height) {
            throw ImageError(name, "cannot decode image: " + stb_reason());
        }
        for (std::size_t i = 0; i < pixels; ++i) {
            const stbi_us* p = decoded.get() + 3 * i;
            image.pixels[i] = {srgb_to_linear(p[0] / 65535.0f), srgb_to_linear(p[1] / 65535.0f),
                               srgb_to_linear(p[2] / 65535.0f)};
        }
    } else {
        const std::unique_ptr<stbi_uc, StbFree> decoded(
            stbi_load_from_memory(data, length, &w, &h, &n, 3));
        if (!decoded || w != width || h != height) {
            throw ImageError(name, "cannot decode image: " + stb_reason());
        }
        const auto& table = srgb8_table();
        for (std::size_t i = 0; i < pixels; ++i) {
            const stbi_uc* p = decoded.get() + 3 * i;
            image.pixels[i] = {table[p[0]], table[p[1]], table[p[2]]};
        }
    }
    return image;
}

Image load_texture_image(const std::filesystem::path& path) {
    std::error_code ec;
    const auto size = std::filesystem::file_size(path, ec);
    if (!ec && size > kMaxTextureFileBytes) {
        throw ImageError(path,
                         "texture file is larger than 1 GiB (" + std::to_string(size) + " bytes)");
    }
    const std::vector<unsigned char> bytes = read_whole_file(path);  // names the file on failure
    return decode_texture_image(bytes, path);
}

}  // namespace glint
