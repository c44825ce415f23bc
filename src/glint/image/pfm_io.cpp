// PFM reading and writing: a short text header, then raw 32-bit floats, bottom row first.
#include "glint/image/pfm_io.h"

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "glint/image/file_io.h"
#include "glint/image/image_limits.h"
#include "glint/image/netpbm_tokenizer.h"

namespace glint {
namespace {

std::uint32_t byte_swap(std::uint32_t v) {
    return (v >> 24) | ((v >> 8) & 0xff00u) | ((v << 8) & 0xff0000u) | (v << 24);
}

void store_little_endian(float value, unsigned char* out) {
    std::uint32_t bits = std::bit_cast<std::uint32_t>(value);
    if constexpr (std::endian::native == std::endian::big) bits = byte_swap(bits);
    std::memcpy(out, &bits, 4);
}

float load(const unsigned char* in, bool little_endian) {
    std::uint32_t bits;
    std::memcpy(&bits, in, 4);
    if (little_endian != (std::endian::native == std::endian::little)) bits = byte_swap(bits);
    return std::bit_cast<float>(bits);
}

}  // namespace

void write_pfm(const std::filesystem::path& path, const Image& image) {
    check_image_shape(path, image);
    const std::string header =
        "PF\n" + std::to_string(image.width) + " " + std::to_string(image.height) + "\n-1.0\n";
    std::vector<unsigned char> data(image.pixels.size() * 12);
    unsigned char* out = data.data();
    for (int y = image.height - 1; y >= 0; --y) {
        for (int x = 0; x < image.width; ++x, out += 12) {
            const Color& c = image.at(x, y);
            store_little_endian(c.r, out);
            store_little_endian(c.g, out + 4);
            store_little_endian(c.b, out + 8);
        }
    }
    UniqueFile file = open_file(path, "wb");
    write_bytes(file.get(), header.data(), header.size(), path);
    write_bytes(file.get(), data.data(), data.size(), path);
    close_written_file(std::move(file), path);
}

Image read_pfm(const std::filesystem::path& path) {
    const std::vector<unsigned char> bytes = read_whole_file(path);
    NetpbmTokenizer tokens(bytes, path, "PFM", /*allow_comments=*/false);
    const std::string_view magic = tokens.next_token();
    if (magic != "PF" && magic != "Pf") {
        throw tokens.malformed("bad magic number " + quote_header_token(magic) +
                               "; expected PF or Pf");
    }
    const int channels = magic == "PF" ? 3 : 1;
    const std::int64_t width = tokens.next_positive("width", kMaxImageDimension);
    const std::int64_t height = tokens.next_positive("height", kMaxImageDimension);
    check_image_size(path, width, height);

    const std::string_view scale_token = tokens.next_token();
    double scale = 0;
    const auto [end, error] =
        std::from_chars(scale_token.data(), scale_token.data() + scale_token.size(), scale);
    if (error != std::errc{} || end != scale_token.data() + scale_token.size() ||
        !std::isfinite(scale) || scale == 0) {
        throw tokens.malformed(
            "scale must be a non-zero number (negative for little-endian), got " +
            quote_header_token(scale_token));
    }
    const bool little_endian = scale < 0;

    const auto start = tokens.raster_start();
    if (!start) throw tokens.malformed("no single whitespace byte between scale and pixel data");
    const std::int64_t expected = width * height * channels * 4;
    const std::int64_t available = std::int64_t(bytes.size()) - std::int64_t(*start);
    if (available < expected) {
        throw tokens.malformed("pixel data truncated: expected " + std::to_string(expected) +
                               " bytes, found " + std::to_string(available));
    }

    Image image(static_cast<int>(width), static_cast<int>(height));
    const unsigned char* in = bytes.data() + *start;
    for (int y = image.height - 1; y >= 0; --y) {
        for (int x = 0; x < image.width; ++x, in += 4 * channels) {
            image.at(x, y) = channels == 3
                                 ? Color(load(in, little_endian), load(in + 4, little_endian),
                                         load(in + 8, little_endian))
                                 : Color::gray(load(in, little_endian));
        }
    }
    return image;
}

}  // namespace glint
