// stb_image behind glint's Image: size checks first, then decoding, then sRGB to linear.
#include "glint/image/texture_file.h"

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "glint/image/exr_io.h"
#include "glint/image/file_io.h"
#include "glint/image/image_error.h"
#include "glint/image/image_format.h"
#include "glint/image/image_limits.h"
#include "glint/image/pfm_io.h"
#include "glint/image/srgb.h"
#include "glint/image/stb_hazards.h"

// Only the formats glint documents; static so that nothing clashes with a libstb linked elsewhere.
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#define STBI_ONLY_JPEG
#define STBI_ONLY_HDR
#define STBI_ONLY_TGA
#define STBI_ONLY_BMP
#define STBI_NO_STDIO
// stb reads parts of its decoder's state that a damaged file never set, such as the Huffman and
// quantization tables of a JPEG scan that no segment defined: zeroed memory makes them empty
// tables instead of whatever the heap held (found by fuzzing: reports that came and went, and
// valgrind's uninitialised reads).
#define STBI_MALLOC(size) std::calloc(1, size)
#define STBI_REALLOC(p, size) std::realloc(p, size)
#define STBI_FREE(p) std::free(p)
// stb_image 2.27's JPEG bit reader stops filling at a marker inside a block, and its bit count
// goes negative; its next fill then shifts a zero byte by more than 31 bits (2.28 checks the
// count). The value is zero either way, so UBSan's shift-exponent check is off for stb's functions
// alone (found by fuzzing: tests/fuzz/crashes/texture).
#if defined(__clang__)
#pragma clang attribute push(__attribute__((no_sanitize("shift-exponent"))), apply_to = function)
#endif
#include <stb/stb_image.h>
#if defined(__clang__)
#pragma clang attribute pop
#endif

namespace glint {

namespace {

struct StbFree {
    void operator()(void* p) const { stbi_image_free(p); }
};

std::string stb_reason() {
    const char* reason = stbi_failure_reason();
    return reason && *reason ? reason : "unknown error";
}

// stb_image reading from memory through callbacks, noting whether a decoder asked for bytes
// beyond the end: stb hands it zeros, which would turn a truncated file into an image with a
// black end, without a word.
class StbMemoryReader {
public:
    explicit StbMemoryReader(std::span<const unsigned char> bytes) : bytes_(bytes) {}

    static const stbi_io_callbacks& callbacks() {
        static const stbi_io_callbacks c{read, skip, eof};
        return c;
    }
    bool ran_out() const { return ran_out_; }

private:
    static int read(void* user, char* data, int size) {
        auto& r = *static_cast<StbMemoryReader*>(user);
        const std::size_t n = std::min(std::size_t(std::max(size, 0)), r.bytes_.size() - r.at_);
        if (n == 0 && size > 0) r.ran_out_ = true;
        if (n > 0) std::memcpy(data, r.bytes_.data() + r.at_, n);
        r.at_ += n;
        return int(n);
    }
    static void skip(void* user, int n) {
        auto& r = *static_cast<StbMemoryReader*>(user);
        if (n < 0) {  // stb skips back only within what it has read
            r.at_ -= std::min(r.at_, std::size_t(-std::int64_t(n)));
            return;
        }
        if (std::size_t(n) > r.bytes_.size() - r.at_) r.ran_out_ = true;
        r.at_ += std::min(std::size_t(n), r.bytes_.size() - r.at_);
    }
    static int eof(void* user) {
        const auto& r = *static_cast<StbMemoryReader*>(user);
        return r.at_ >= r.bytes_.size() ? 1 : 0;
    }

    std::span<const unsigned char> bytes_;
    std::size_t at_ = 0;
    bool ran_out_ = false;
};

// Decodes with stb's `load` (8-bit, 16-bit or float) through a StbMemoryReader: nothing, with the
// reason in `error`, when stb fails or the data ends early.
template <typename T, typename Load>
std::unique_ptr<T, StbFree> decode(std::span<const unsigned char> bytes, Load load, int width,
                                   int height, std::string& error) {
    StbMemoryReader reader(bytes);
    int w = 0, h = 0, n = 0;
    std::unique_ptr<T, StbFree> decoded(
        load(&StbMemoryReader::callbacks(), &reader, &w, &h, &n, 3));
    if (reader.ran_out()) {
        error = kTruncatedTexture;
        return nullptr;
    }
    if (!decoded || w != width || h != height) {
        error = stb_reason();
        return nullptr;
    }
    return decoded;
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

Image decode_texture_image(std::span<const unsigned char> file_bytes,
                           const std::filesystem::path& name, std::int64_t max_pixels) {
    if (file_bytes.size() > kMaxDecodableTextureBytes) {
        throw ImageError(name, "texture is larger than the decoder takes (2 GiB)");
    }
    const std::vector<unsigned char> repaired = png_without_empty_data(file_bytes);
    const std::span<const unsigned char> bytes =
        repaired.empty() ? file_bytes : std::span<const unsigned char>(repaired);
    const auto* data = bytes.data();
    const int length = int(bytes.size());
    // Before stbi_info, which reads the tables that come before a JPEG's frame header.
    if (const auto overflow = jpeg_overflow(bytes))
        throw ImageError(name, "cannot decode JPEG image: " + *overflow);
    int width = 0, height = 0, channels = 0;
    if (!stbi_info_from_memory(data, length, &width, &height, &channels)) {
        throw ImageError(name, "not a PNG, JPEG, HDR, TGA or BMP image stb_image can read (" +
                                   stb_reason() + ")");
    }
    check_image_size(name, width, height, max_pixels);
    const bool hdr = stbi_is_hdr_from_memory(data, length);
    if (too_short_for_size(bytes, width, height)) {
        throw ImageError(name,
                         std::string(hdr ? "cannot decode HDR image: " : "cannot decode image: ") +
                             kTruncatedTexture);
    }

    Image image(width, height);
    const std::size_t pixels = std::size_t(width) * std::size_t(height);
    std::string error;
    if (hdr) {
        if (const auto hang = hdr_hang(bytes, width, height))
            throw ImageError(name, "cannot decode HDR image: " + *hang);
        const auto decoded = decode<float>(bytes, stbi_loadf_from_callbacks, width, height, error);
        if (!decoded) throw ImageError(name, "cannot decode HDR image: " + error);
        for (std::size_t i = 0; i < pixels; ++i) {
            const float* p = decoded.get() + 3 * i;
            image.pixels[i] = {p[0], p[1], p[2]};
        }
    } else if (stbi_is_16_bit_from_memory(data, length)) {
        const auto decoded =
            decode<stbi_us>(bytes, stbi_load_16_from_callbacks, width, height, error);
        if (!decoded) throw ImageError(name, "cannot decode image: " + error);
        for (std::size_t i = 0; i < pixels; ++i) {
            const stbi_us* p = decoded.get() + 3 * i;
            image.pixels[i] = {srgb_to_linear(p[0] / 65535.0f), srgb_to_linear(p[1] / 65535.0f),
                               srgb_to_linear(p[2] / 65535.0f)};
        }
    } else {
        const auto decoded = decode<stbi_uc>(bytes, stbi_load_from_callbacks, width, height, error);
        if (!decoded) throw ImageError(name, "cannot decode image: " + error);
        const auto& table = srgb8_table();
        for (std::size_t i = 0; i < pixels; ++i) {
            const stbi_uc* p = decoded.get() + 3 * i;
            image.pixels[i] = {table[p[0]], table[p[1]], table[p[2]]};
        }
    }
    return image;
}

Image load_texture_image(const std::filesystem::path& path, std::uintmax_t max_bytes,
                         std::int64_t max_pixels) {
    max_bytes = std::min(max_bytes, kMaxDecodableTextureBytes);
    std::error_code ec;
    // A pipe or a device (/dev/zero) has no size to check and might never end.
    const auto status = std::filesystem::status(path, ec);
    if (!ec && std::filesystem::exists(status) && !std::filesystem::is_regular_file(status))
        throw ImageError(path, "texture file is not a regular file");
    const auto size = std::filesystem::file_size(path, ec);
    if (!ec && size > max_bytes) {
        throw ImageError(path, "texture file is " + std::to_string(size) +
                                   " bytes, more than the limit of " + std::to_string(max_bytes));
    }
    const std::optional<ImageFormat> format = format_from_extension(path);
    if (format == ImageFormat::exr || format == ImageFormat::pfm) {
        Image image = *format == ImageFormat::exr ? read_exr(path) : read_pfm(path);
        check_image_size(path, image.width, image.height, max_pixels);
        check_texture_values(path, image);
        return image;
    }
    const std::vector<unsigned char> bytes = read_whole_file(path);  // names the file on failure
    return decode_texture_image(bytes, path, max_pixels);
}

void check_texture_values(const std::filesystem::path& path, const Image& image) {
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const Color c = image.at(x, y);
            for (const float v : {c.r, c.g, c.b}) {
                if (std::isfinite(v) && v >= 0) continue;
                throw ImageError(path, "pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                                           ") holds " + std::to_string(v) +
                                           "; a texture's values must be finite and >= 0");
            }
        }
    }
}

}  // namespace glint
