// The shared quantiser of the 8-bit writers, so PNG and PPM of one image hold the same bytes.
#include "glint/image/quantize.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <bit>
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

SampleRandom dither_random(int x, int y) {
    const std::uint64_t pixel = (std::uint64_t(std::uint32_t(y)) << 32) | std::uint32_t(x);
    return SampleRandom(pixel, 0, kDitherSeed);
}

// Levels in fixed point, in units of 2^-24 LSB: the 24 bits of a dither's random number line up
// with a level's fraction, so the decisions below are integer sums and masks.
constexpr int kFractionBits = 24;
constexpr std::uint32_t kFraction = (1u << kFractionBits) - 1;

// The sRGB curve's level (linear_to_srgb(v) * 255, in fixed point) where it takes a pow: v in
// (0.0031308, 1], from a table of it at the floats whose low 13 mantissa bits are zero (the
// exponent and ten mantissa bits index it), linearly interpolated. The interpolation's error is
// below 1e-5 LSB (h^2/8 |f''| on each 2^-10 relative step).
class SrgbLevelTable {
public:
    static constexpr std::uint32_t kShift = 13;
    static constexpr std::uint32_t kFirst = std::bit_cast<std::uint32_t>(0.0031308f) >> kShift;
    static constexpr std::uint32_t kLast = std::bit_cast<std::uint32_t>(1.0f) >> kShift;

    SrgbLevelTable() {
        for (std::uint32_t i = kFirst; i <= kLast + 1; ++i) {
            const double v = std::min(double(std::bit_cast<float>(i << kShift)), 1.0);
            const double level = (1.055 * std::pow(v, 1 / 2.4) - 0.055) * 255;
            level_[i - kFirst] = std::uint32_t(std::lround(std::ldexp(level, kFractionBits)));
        }
    }

    std::uint32_t operator()(float v) const {
        const std::uint32_t bits = std::bit_cast<std::uint32_t>(v);
        const std::uint32_t i = (bits >> kShift) - kFirst;
        const std::uint64_t t = bits & ((1u << kShift) - 1);
        return level_[i] + std::uint32_t(((level_[i + 1] - level_[i]) * t) >> kShift);
    }

private:
    std::array<std::uint32_t, kLast - kFirst + 2> level_{};
};

// How far a level by the table may be from the exact one (5e-4 LSB), with room to spare: a value
// this close to a decision's edge is quantised the exact way. The exact way's own float
// rounding is a few 1e-5 LSB.
constexpr std::uint32_t kTableError = 8400;
constexpr auto kExactLevelFixed = std::uint32_t(kExactLevelTolerance * (1 << kFractionBits));

const SrgbLevelTable& srgb_level_table() {
    static const SrgbLevelTable table;
    return table;
}

// quantize_srgb8(linear, x, y, channel) by the table: the same byte, as any value whose
// decisions the table's error could change is handed to the exact way.
std::uint8_t quantize_by_table(const SrgbLevelTable& table, float linear,
                               const SampleRandom& random, int x, int y, int channel) {
    if (!(linear > 0)) return 0;  // and NaN: as the exact way, which clamps
    if (linear >= 1) return 255;
    const std::uint32_t level =
        linear > 0.0031308f
            ? table(linear)
            : std::uint32_t(std::ldexp(linear_to_srgb(linear) * 255, kFractionBits));
    const std::uint32_t fraction = level & kFraction;
    const std::uint32_t off_level = std::min(fraction, kFraction + 1 - fraction);
    const std::uint32_t from_edge =
        off_level > kExactLevelFixed ? off_level - kExactLevelFixed : kExactLevelFixed - off_level;
    if (from_edge < kTableError) return quantize_srgb8(linear, x, y, channel);
    if (off_level < kExactLevelFixed) return std::uint8_t((level + (1u << 23)) >> kFractionBits);
    // level + 0.5 + noise, the noise's 24 random bits less a half
    const auto noise = std::uint32_t(random(std::uint64_t(channel)) * 0x1.0p24f);
    const std::uint64_t dithered = std::uint64_t(level) + noise;
    const std::uint32_t dithered_fraction = std::uint32_t(dithered) & kFraction;
    if (dithered_fraction < kTableError || dithered_fraction > kFraction + 1 - kTableError)
        return quantize_srgb8(linear, x, y, channel);
    return std::uint8_t(std::min<std::uint64_t>(dithered >> kFractionBits, 255));
}

}  // namespace

std::uint8_t quantize_srgb8(float linear, int x, int y, int channel) {
    if (std::isnan(linear)) return 0;
    const float level = linear_to_srgb(linear) * 255;  // in [0, 255]
    const float nearest = std::round(level);
    if (std::abs(level - nearest) < kExactLevelTolerance) return std::uint8_t(nearest);
    const float noise = dither_random(x, y)(std::uint64_t(channel)) - 0.5f;
    return std::uint8_t(std::clamp(std::floor(level + 0.5f + noise), 0.0f, 255.0f));
}

void quantize_srgb8_row(const Image& image, int y, std::uint8_t* out) {
    const SrgbLevelTable& table = srgb_level_table();
    for (int x = 0; x < image.width; ++x) {
        const Color& c = image.at(x, y);
        const SampleRandom random = dither_random(x, y);
        out[3 * x] = quantize_by_table(table, c.r, random, x, y, 0);
        out[3 * x + 1] = quantize_by_table(table, c.g, random, x, y, 1);
        out[3 * x + 2] = quantize_by_table(table, c.b, random, x, y, 2);
    }
}

std::vector<std::uint8_t> quantize_srgb8(const Image& image) {
    std::vector<std::uint8_t> bytes(image.pixels.size() * 3);
    // Rows in parallel: each byte depends on its value and place alone, so the bytes are the same
    // for any number of threads.
    tbb::parallel_for(0, image.height, [&](int y) {
        quantize_srgb8_row(image, y, bytes.data() + std::size_t(y) * std::size_t(image.width) * 3);
    });
    return bytes;
}

}  // namespace glint
