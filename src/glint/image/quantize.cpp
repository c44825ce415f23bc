// The shared quantiser of the 8-bit writers, so PNG and PPM of one image hold the same bytes.
#include "glint/image/quantize.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "glint/image/srgb.h"
#include "glint/sampling/random.h"

namespace glint {
namespace {

constexpr std::uint64_t kDitherSeed = 0x676c696e74ull;  // "glint"

// How far from an 8-bit level (in LSB) a value may be and still count as that level. Decoding
// an 8-bit file and re-encoding it lands within ~2e-5 LSB of the original byte; keeping such
// values exact makes 8-bit images round-trip byte for byte, at a bias far below what dithering
// could resolve.
constexpr float kExactLevelTolerance = 1e-3f;

}  // namespace

std::uint8_t quantize_srgb8(float linear, int x, int y, int channel) {
    if (std::isnan(linear)) return 0;
    const float level = linear_to_srgb(linear) * 255;  // in [0, 255]
    const float nearest = std::round(level);
    if (std::abs(level - nearest) < kExactLevelTolerance) return std::uint8_t(nearest);

    const std::uint64_t pixel = (std::uint64_t(std::uint32_t(y)) << 32) | std::uint32_t(x);
    const float noise = random_float(pixel, 0, std::uint64_t(channel), kDitherSeed) - 0.5f;
    return std::uint8_t(std::clamp(std::floor(level + 0.5f + noise), 0.0f, 255.0f));
}

std::vector<std::uint8_t> quantize_srgb8(const Image& image) {
    std::vector<std::uint8_t> bytes(image.pixels.size() * 3);
    // Rows in parallel: each byte depends on its value and place alone, so the bytes are the same
    // for any number of threads.
    tbb::parallel_for(0, image.height, [&](int y) {
        std::uint8_t* row = bytes.data() + std::size_t(y) * std::size_t(image.width) * 3;
        for (int x = 0; x < image.width; ++x) {
            const Color& c = image.at(x, y);
            row[3 * x] = quantize_srgb8(c.r, x, y, 0);
            row[3 * x + 1] = quantize_srgb8(c.g, x, y, 1);
            row[3 * x + 2] = quantize_srgb8(c.b, x, y, 2);
        }
    });
    return bytes;
}

}  // namespace glint
