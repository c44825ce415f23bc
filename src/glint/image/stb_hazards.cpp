// The walks through texture data that find what stb_image would hang on or overflow with.
#include "glint/image/stb_hazards.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <utility>

namespace glint {

// The scanlines are walked as stb walks them (stb refuses other damage itself).
std::optional<std::string> hdr_hang(std::span<const unsigned char> bytes, int width, int height) {
    if (width < 8 || width >= 32768) return std::nullopt;  // flat data, read straight
    const std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    // stb reads the header's lines into a C string, so the header ends at a line that is empty
    // or starts with a NUL; the size line follows, then the data.
    constexpr auto npos = std::string_view::npos;
    std::size_t p = text.find('\n');
    while (p != npos && p + 1 < text.size() && text[p + 1] != '\n' && text[p + 1] != '\0')
        p = text.find('\n', p + 1);
    if (p == npos || p + 1 >= text.size()) return std::nullopt;
    p = text.find('\n', p + 1);                 // the end of the line that ends the header
    if (p != npos) p = text.find('\n', p + 1);  // the end of the size line
    if (p == npos) return std::nullopt;
    ++p;
    const auto next = [&]() -> int { return p < bytes.size() ? bytes[p++] : -1; };
    for (int j = 0; j < height; ++j) {
        const int c1 = next(), c2 = next(), high = next();
        if (high < 0) return kTruncatedTexture;
        if (c1 != 2 || c2 != 2 || (high & 0x80)) return std::nullopt;  // flat from here on
        if (next() < 0) return kTruncatedTexture;
        for (int channel = 0; channel < 4; ++channel) {
            for (int i = 0; i < width;) {
                const int count = next();
                if (count < 0) return kTruncatedTexture;
                if (count == 0)
                    return "corrupt HDR: a run-length count of 0 in scanline " + std::to_string(j);
                const int run = count > 128 ? count - 128 : count;
                const std::size_t bytes_of_run = count > 128 ? 1 : std::size_t(count);
                if (bytes_of_run > bytes.size() - p) return kTruncatedTexture;
                p += bytes_of_run;
                i += run;
            }
        }
    }
    return std::nullopt;
}

namespace {

bool starts_with(std::span<const unsigned char> bytes, std::string_view magic) {
    return bytes.size() >= magic.size() &&
           std::string_view(reinterpret_cast<const char*>(bytes.data()), magic.size()) == magic;
}

// As stb tells a JPEG: its first marker, after any fill bytes FF, is SOI (FF D8).
bool is_jpeg(std::span<const unsigned char> bytes) {
    if (bytes.empty() || bytes[0] != 0xFF) return false;
    std::size_t p = 1;
    while (p < bytes.size() && bytes[p] == 0xFF) ++p;
    return p < bytes.size() && bytes[p] == 0xD8;
}

std::uint64_t big_endian32(std::span<const unsigned char> bytes, std::size_t at) {
    return std::uint64_t(bytes[at]) << 24 | std::uint64_t(bytes[at + 1]) << 16 |
           std::uint64_t(bytes[at + 2]) << 8 | bytes[at + 3];
}

// The fewest bytes a TGA of this size takes: a run-length packet holds at most 128 pixels.
std::uint64_t tga_bytes(std::span<const unsigned char> bytes, std::uint64_t pixels) {
    if (bytes.size() < 18) return 18;
    const std::uint64_t palette_entry_bytes = (std::uint64_t(bytes[7]) + 7) / 8;
    const std::uint64_t palette_bytes = (std::uint64_t(bytes[5]) | std::uint64_t(bytes[6]) << 8) *
                                        (bytes[1] ? palette_entry_bytes : 0);
    const std::uint64_t pixel_bytes = (std::uint64_t(bytes[16]) + 7) / 8;
    const bool run_length = bytes[2] >= 9;
    return 18 + bytes[0] + palette_bytes +
           (run_length ? (pixels + 127) / 128 * (1 + pixel_bytes) : pixels * pixel_bytes);
}

// Deflate packs at most 1032 bytes into one; a row is a filter byte and its packed samples.
std::uint64_t png_bytes(std::span<const unsigned char> bytes, std::uint64_t width,
                        std::uint64_t height) {
    if (bytes.size() < 26) return 26;
    const unsigned depth = bytes[24], colour_type = bytes[25];
    const unsigned channels = colour_type == 2   ? 3
                              : colour_type == 4 ? 2
                              : colour_type == 6 ? 4
                                                 : 1;
    const std::uint64_t row = 1 + (width * depth * channels + 7) / 8;
    return height * row / 1032;
}

// Whether a PNG chunk (a 4-byte length, a 4-byte type, the data, a 4-byte CRC) claims more bytes
// than the file has left: stb grows its buffer for an IDAT chunk's claimed length before reading
// it (2 GiB for a 185-byte file).
bool png_chunk_overruns(std::span<const unsigned char> bytes) {
    for (std::size_t p = 8; p + 8 <= bytes.size();) {
        const std::uint64_t length = big_endian32(bytes, p);
        if (length + 12 > bytes.size() - p) return true;
        if (starts_with(bytes.subspan(p + 4), "IEND")) return false;
        p += 12 + std::size_t(length);
    }
    return false;
}

}  // namespace

bool too_short_for_size(std::span<const unsigned char> bytes, int width, int height) {
    const std::uint64_t w = std::uint64_t(width), h = std::uint64_t(height), pixels = w * h;
    std::uint64_t least = 0;
    if (starts_with(bytes, "\x89PNG")) {
        if (png_chunk_overruns(bytes)) return true;
        least = png_bytes(bytes, w, h);
    } else if (is_jpeg(bytes)) {
        // Every 8 x 8 block of the full-resolution component codes its DC term in 1 bit or more.
        least = pixels / 512;
    } else if (starts_with(bytes, "BM")) {
        if (bytes.size() < 30) return true;  // the header ends before the bits per pixel
        // The bits per pixel follow 16-bit sides in the old 12-byte header, 32-bit ones in the
        // others; a count of 0 (not one stb reads) is taken as 1, the fewest.
        const std::size_t at = bytes[14] == 12 && bytes[15] == 0 ? 24 : 28;
        const unsigned bits = std::max(1u, bytes[at] | unsigned(bytes[at + 1]) << 8);
        least = h * ((w * bits + 7) / 8);  // stb reads no run-length BMPs
    } else if (starts_with(bytes, "#?")) {
        // A run-length scanline: a 4-byte header, then per channel 2 bytes a run of up to 127.
        least = h * (4 + 4 * 2 * ((w + 126) / 127));
    } else {
        least = tga_bytes(bytes, pixels);
    }
    return bytes.size() < least;
}

std::vector<unsigned char> png_without_empty_data(std::span<const unsigned char> bytes) {
    if (!starts_with(bytes, "\x89PNG\r\n\x1a\n")) return {};
    // Chunks: a 4-byte length, a 4-byte type, the data, a 4-byte CRC.
    std::vector<std::pair<std::size_t, std::size_t>> empty_data;  // offset and size of each
    std::size_t p = 8;
    while (p + 12 <= bytes.size()) {
        const std::uint64_t length = big_endian32(bytes, p);
        if (length > bytes.size() - p - 12) break;
        if (length == 0 && starts_with(bytes.subspan(p + 4), "IDAT")) empty_data.push_back({p, 12});
        p += 12 + std::size_t(length);
    }
    if (empty_data.empty()) return {};
    std::vector<unsigned char> out;
    out.reserve(bytes.size());
    std::size_t from = 0;
    for (const auto& [at, size] : empty_data) {
        out.insert(out.end(), bytes.begin() + std::ptrdiff_t(from),
                   bytes.begin() + std::ptrdiff_t(at));
        from = at + size;
    }
    out.insert(out.end(), bytes.begin() + std::ptrdiff_t(from), bytes.end());
    return out;
}

// Every FF C4 pair is taken for a DHT marker, wherever it is: stb's reading of the segments
// drifts from their lengths on damaged data (it reads tables past a segment's end), so only the
// superset is sure to hold every table stb reads. In a sound file FF C4 appears only as the
// marker (entropy-coded data escapes FF), or inside an embedded thumbnail's own sound tables.
std::optional<std::string> jpeg_overflow(std::span<const unsigned char> bytes) {
    if (!is_jpeg(bytes)) return std::nullopt;
    const std::size_t size = bytes.size();
    for (std::size_t p = 0; p + 4 <= size; ++p) {
        if (bytes[p] != 0xFF || bytes[p + 1] != 0xC4) continue;
        const std::size_t length = std::size_t(bytes[p + 2]) << 8 | bytes[p + 3];
        // stb reads tables while the length it counts down stays positive, even past the
        // segment: each a class byte, 16 counts, and as many symbols as they add up to.
        long left = long(length) - 2;
        std::size_t q = p + 4;
        while (left > 0 && q < size) {
            int codes = 0;  // past the end of the data stb reads zeros
            for (std::size_t i = 1; i <= 16 && q + i < size; ++i) codes += bytes[q + i];
            if (codes > 256) {
                return "corrupt JPEG: a Huffman table has " + std::to_string(codes) +
                       " codes, more than 256";
            }
            left -= 17 + codes;
            q += 17 + std::size_t(codes);
        }
    }
    return std::nullopt;
}

}  // namespace glint
