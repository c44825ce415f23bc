// PPM reading and writing (Netpbm's ppm(5)), parsed in memory so every size is checked
// against the bytes actually present before anything is allocated.
#include "glint/image/ppm_io.h"

#include <cstdint>
#include <string>
#include <vector>

#include "glint/image/file_io.h"
#include "glint/image/image_limits.h"
#include "glint/image/netpbm_tokenizer.h"
#include "glint/image/quantize.h"
#include "glint/image/srgb.h"

namespace glint {
namespace {

constexpr std::int64_t kMaxMaxval = 65535;

std::string pixel_of_sample(std::int64_t sample_index, std::int64_t width) {
    const std::int64_t pixel = sample_index / 3;
    return "(" + std::to_string(pixel % width) + ", " + std::to_string(pixel / width) + ")";
}

// The encoded samples, in file order, checked against maxval.
std::vector<std::uint16_t> read_samples(const std::vector<unsigned char>& bytes,
                                        NetpbmTokenizer& tokens, bool ascii, std::int64_t width,
                                        std::int64_t count, std::int64_t maxval) {
    if (ascii) {
        // Every sample takes at least one byte: reject absurd sizes before allocating.
        if (std::int64_t(bytes.size()) < count) {
            throw tokens.malformed("pixel data truncated: expected " + std::to_string(count) +
                                   " samples in a file of " + std::to_string(bytes.size()) +
                                   " bytes");
        }
        std::vector<std::uint16_t> samples(std::size_t(count), 0);
        for (std::int64_t i = 0; i < count; ++i) {
            const std::string_view token = tokens.next_token();
            if (token.empty()) {
                throw tokens.malformed("pixel data truncated: expected " + std::to_string(count) +
                                       " samples, found " + std::to_string(i));
            }
            const auto value = parse_decimal(token, maxval);
            if (!value) {
                throw tokens.malformed("bad sample " + quote_header_token(token) + " at pixel " +
                                       pixel_of_sample(i, width) + " (maxval is " +
                                       std::to_string(maxval) + ")");
            }
            samples[std::size_t(i)] = std::uint16_t(*value);
        }
        return samples;
    }

    const auto start = tokens.raster_start();
    if (!start) throw tokens.malformed("no single whitespace byte between maxval and pixel data");
    const std::int64_t bytes_per_sample = maxval < 256 ? 1 : 2;
    const std::int64_t expected = count * bytes_per_sample;
    const std::int64_t available = std::int64_t(bytes.size()) - std::int64_t(*start);
    if (available < expected) {
        throw tokens.malformed("pixel data truncated: expected " + std::to_string(expected) +
                               " bytes, found " + std::to_string(available));
    }
    std::vector<std::uint16_t> samples(std::size_t(count), 0);
    const unsigned char* data = bytes.data() + *start;
    for (std::int64_t i = 0; i < count; ++i) {
        const unsigned value =
            bytes_per_sample == 1 ? data[i] : (data[2 * i] << 8) | data[2 * i + 1];
        if (value > maxval) {
            throw tokens.malformed("sample " + std::to_string(value) + " at pixel " +
                                   pixel_of_sample(i, width) + " exceeds maxval " +
                                   std::to_string(maxval));
        }
        samples[std::size_t(i)] = std::uint16_t(value);
    }
    return samples;
}

}  // namespace

void write_ppm(const std::filesystem::path& path, const Image& image, PpmEncoding encoding) {
    check_image_shape(path, image);
    const std::vector<std::uint8_t> bytes = quantize_srgb8(image);
    const bool ascii = encoding == PpmEncoding::ascii;
    std::string header = std::string(ascii ? "P3\n" : "P6\n") + std::to_string(image.width) + " " +
                         std::to_string(image.height) + "\n255\n";

    UniqueFile file = open_file(path, "wb");
    write_bytes(file.get(), header.data(), header.size(), path);
    if (ascii) {
        // One pixel a line keeps lines under the 70 characters the plain format asks for.
        std::string text;
        text.reserve(bytes.size() * 4);
        for (std::size_t i = 0; i < bytes.size(); i += 3) {
            text += std::to_string(bytes[i]) + ' ' + std::to_string(bytes[i + 1]) + ' ' +
                    std::to_string(bytes[i + 2]) + '\n';
        }
        write_bytes(file.get(), text.data(), text.size(), path);
    } else {
        write_bytes(file.get(), bytes.data(), bytes.size(), path);
    }
    close_written_file(std::move(file), path);
}

Image read_ppm(const std::filesystem::path& path) {
    const std::vector<unsigned char> bytes = read_whole_file(path);
    NetpbmTokenizer tokens(bytes, path, "PPM", /*allow_comments=*/true);
    const std::string_view magic = tokens.next_token();
    if (magic != "P3" && magic != "P6") {
        throw tokens.malformed("bad magic number " + quote_header_token(magic) +
                               "; expected P3 or P6");
    }
    const bool ascii = magic == "P3";
    const std::int64_t width = tokens.next_positive("width", kMaxImageDimension);
    const std::int64_t height = tokens.next_positive("height", kMaxImageDimension);
    const std::int64_t maxval = tokens.next_positive("maxval", kMaxMaxval);
    check_image_size(path, width, height);

    const std::vector<std::uint16_t> samples =
        read_samples(bytes, tokens, ascii, width, width * height * 3, maxval);
    std::vector<float> decode(std::size_t(maxval) + 1);
    for (std::size_t v = 0; v < decode.size(); ++v) {
        decode[v] = srgb_to_linear(float(v) / float(maxval));
    }
    Image image(static_cast<int>(width), static_cast<int>(height));
    for (std::size_t i = 0; i < image.pixels.size(); ++i) {
        image.pixels[i] = {decode[samples[3 * i]], decode[samples[3 * i + 1]],
                           decode[samples[3 * i + 2]]};
    }
    return image;
}

}  // namespace glint
