// The walks through texture data that find what stb_image would hang on or overflow with.
#include "glint/image/stb_hazards.h"

#include <cstddef>
#include <string_view>

namespace glint {

// The scanlines are walked as stb walks them (stb refuses other damage itself).
std::optional<std::string> hdr_hang(std::span<const unsigned char> bytes, int width, int height) {
    if (width < 8 || width >= 32768) return std::nullopt;  // flat data, read straight
    const std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    std::size_t p = text.find("\n\n");  // the header's end; the size line follows
    if (p != std::string_view::npos) p = text.find('\n', p + 2);
    if (p == std::string_view::npos) return std::nullopt;
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

bool tga_too_short(std::span<const unsigned char> bytes, int width, int height) {
    const auto starts = [&](std::string_view magic) {
        return bytes.size() >= magic.size() &&
               std::string_view(reinterpret_cast<const char*>(bytes.data()), magic.size()) == magic;
    };
    if (starts("\x89PNG") || starts("\xFF\xD8") || starts("BM") || starts("#?")) return false;
    if (bytes.size() < 18) return true;
    const std::size_t palette_entry_bytes = (std::size_t(bytes[7]) + 7) / 8;
    const std::size_t palette_bytes =
        (std::size_t(bytes[5]) | std::size_t(bytes[6]) << 8) * (bytes[1] ? palette_entry_bytes : 0);
    const std::size_t header = 18 + std::size_t(bytes[0]) + palette_bytes;
    const std::size_t pixel_bytes = (std::size_t(bytes[16]) + 7) / 8;
    const std::size_t pixels = std::size_t(width) * std::size_t(height);
    const bool run_length = bytes[2] >= 9;
    const std::size_t data =
        run_length ? (pixels + 127) / 128 * (1 + pixel_bytes) : pixels * pixel_bytes;
    return bytes.size() < header + data;
}

// Markers as stb reads them: segments carry a length and are stepped over whole; between them,
// in entropy-coded data, a 0xFF is followed by 0x00 (a stuffed byte) or a restart marker.
std::optional<std::string> jpeg_overflow(std::span<const unsigned char> bytes) {
    if (bytes.size() < 2 || bytes[0] != 0xFF || bytes[1] != 0xD8) return std::nullopt;
    const std::size_t size = bytes.size();
    std::size_t p = 2;
    while (p + 1 < size) {
        if (bytes[p] != 0xFF) {
            ++p;
            continue;
        }
        const unsigned marker = bytes[p + 1];
        if (marker == 0xFF) {  // fill byte
            ++p;
            continue;
        }
        const bool bare = marker == 0x00 || marker == 0x01 || (marker >= 0xD0 && marker <= 0xD8);
        if (bare) {
            p += 2;
            continue;
        }
        if (marker == 0xD9 || p + 3 >= size) return std::nullopt;  // end of image
        const std::size_t length = std::size_t(bytes[p + 2]) << 8 | bytes[p + 3];
        if (marker == 0xC4) {
            // stb reads tables while the length it counts down stays positive, even past the
            // segment: each a class byte, 16 counts, and as many symbols as they add up to.
            long left = long(length) - 2;
            std::size_t q = p + 4;
            while (left > 0 && q + 17 <= size) {
                int codes = 0;
                for (std::size_t i = 1; i <= 16; ++i) codes += bytes[q + i];
                if (codes > 256) {
                    return "corrupt JPEG: a Huffman table has " + std::to_string(codes) +
                           " codes, more than 256";
                }
                left -= 17 + codes;
                q += 17 + std::size_t(codes);
            }
        }
        p += 2 + length;
    }
    return std::nullopt;
}

}  // namespace glint
