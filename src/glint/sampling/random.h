// Counter-based random numbers: each value is a pure function of its coordinates, so an image
// does not depend on thread count, tile order or the number of machines (DESIGN principle 2).
#pragma once

#include <cstdint>

namespace glint {

// SplitMix64's finaliser (Steele, Lea and Flood 2014): a bijective 64-bit mix.
constexpr std::uint64_t mix64(std::uint64_t z) {
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

// The random numbers of one sample of one pixel, a uniform float in [0, 1) for each dimension:
// what random_float gives, with the hashing of the pixel and sample done once for all dimensions.
class SampleRandom {
public:
    constexpr SampleRandom(std::uint64_t pixel, std::uint64_t sample, std::uint64_t seed)
        : h_(mix64(mix64(mix64(seed + 0x9e3779b97f4a7c15ull) ^ pixel) ^
                   (sample * 0x632be59bd9b4e019ull))) {}

    constexpr float operator()(std::uint64_t dimension) const {
        const std::uint64_t h = mix64(h_ ^ (dimension * 0x8cb92ba72f3d8dd7ull));
        return float(h >> 40) * 0x1.0p-24f;  // 24 random mantissa bits
    }

private:
    std::uint64_t h_;
};

// A uniform float in [0, 1) for the given coordinates: which pixel, which sample of it, which
// dimension of the sample, and the render's seed.
constexpr float random_float(std::uint64_t pixel, std::uint64_t sample, std::uint64_t dimension,
                             std::uint64_t seed) {
    return SampleRandom(pixel, sample, seed)(dimension);
}

}  // namespace glint
