// Where inside its pixel each sample lies. The integrator asks only for offsets, so stochastic
// samplers can replace the regular grid without touching it.
#pragma once

#include <cmath>
#include <cstdint>

#include "glint/math/vector.h"

namespace glint {

enum class SamplerKind { regular };

// n x n regular supersampling: sample i sits at the centre of cell (i mod n, i div n).
class PixelSampler {
public:
    // samples_per_pixel must satisfy is_valid_sample_count(kind, samples_per_pixel).
    PixelSampler(SamplerKind kind, int samples_per_pixel, std::uint64_t seed)
        : kind_(kind),
          spp_(samples_per_pixel),
          grid_(static_cast<int>(std::lround(std::sqrt(double(samples_per_pixel))))),
          seed_(seed) {}

    SamplerKind kind() const { return kind_; }
    int samples_per_pixel() const { return spp_; }
    std::uint64_t seed() const { return seed_; }

    // Offset in [0,1)^2 from the pixel's top-left corner.
    Point2 offset(int sample_index) const {
        const int i = sample_index % grid_, j = sample_index / grid_;
        return {(float(i) + 0.5f) / float(grid_), (float(j) + 0.5f) / float(grid_)};
    }

private:
    SamplerKind kind_;
    int spp_;
    int grid_;
    std::uint64_t seed_;
};

// The regular grid needs a square number of samples (1, 4, 9, 16, ...).
inline bool is_valid_sample_count(SamplerKind kind, int samples_per_pixel) {
    if (samples_per_pixel < 1) return false;
    switch (kind) {
        case SamplerKind::regular: {
            const auto n = std::lround(std::sqrt(double(samples_per_pixel)));
            return n * n == samples_per_pixel;
        }
    }
    return false;
}

}  // namespace glint
