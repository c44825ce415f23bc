// The numbers every pixel sample draws, dimension after dimension (pixel position, lens, time,
// wavelength, then lights and lobes): each a pure function of (pixel, sample index, dimension,
// seed), so an image does not depend on threads, tiles or machines (DESIGN principle 2).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

#include "glint/math/vector.h"

namespace glint {

// regular: the points of each dimension at the centres of a grid of cells, no randomness (for the
//   pixel position, today's n x n supersampling); jittered: one random point in each cell of a
//   grid, correlated multi-jittered so that rows and columns are stratified too (Kensler 2013);
//   sobol: the Sobol sequence, Owen-scrambled (Burley 2020), good for any count and for every
//   prefix of it (adaptive sampling). The camera's dimensions (pixel, lens, time, wavelength) are
//   Sobol's first six, one point of one sequence, so that they are stratified together (a pixel
//   position with a lens position, as depth of field needs); the others are its (0,2)-sequence,
//   shuffled per dimension.
enum class SamplerKind { regular, jittered, sobol };

// The samplers' names, sorted, as scene files and the command line write them.
std::span<const std::string_view> sampler_names();
std::optional<SamplerKind> sampler_from_name(std::string_view name);

// The regular grid of the pixel position needs a square number of samples (1, 4, 9, 16, ...);
// the other kinds take any count >= 1.
bool is_valid_sample_count(SamplerKind kind, int samples_per_pixel);

// The dimensions every sample reserves, whether or not the scene uses them, so that a dimension
// means the same thing in every sample of a pixel.
inline constexpr std::uint32_t kPixelDimension = 0;       // where in the pixel (2D)
inline constexpr std::uint32_t kLensDimension = 1;        // where on the lens (2D)
inline constexpr std::uint32_t kTimeDimension = 2;        // when in the shutter interval (1D)
inline constexpr std::uint32_t kWavelengthDimension = 3;  // which wavelength (1D)
inline constexpr std::uint32_t kFirstFreeDimension = 4;

// The hashes that choose one dimension's pattern in one pixel: the key, and the keys of the
// permutations of its cells, columns and rows; and the pixel's own key, the same in every
// dimension, for what the dimensions share. Every sample of the pixel needs the same ones.
struct PatternKeys {
    std::uint64_t key, cells, columns, rows, pixel;
};

class Sampler {
public:
    // samples_per_pixel is the size of each dimension's pattern: the count the pixels take (or
    // the most they may take); it must satisfy is_valid_sample_count(kind, samples_per_pixel).
    Sampler(SamplerKind kind, int samples_per_pixel, std::uint64_t seed);

    SamplerKind kind() const { return kind_; }
    int samples_per_pixel() const { return spp_; }
    std::uint64_t seed() const { return seed_; }

    // Point `index` of the pattern of `count` points that dimension `dimension` of `pixel`
    // spreads over [0,1)^2. A sample with n sub-samples in one dimension (n shadow rays) takes
    // points sample * n + j of a pattern of samples_per_pixel * n points, so that they are
    // stratified across the pixel's samples together.
    Point2 get_2d(std::uint64_t pixel, std::uint32_t index, std::uint32_t count,
                  std::uint32_t dimension) const {
        return get_2d(pattern_keys(pixel, dimension), index, count, dimension);
    }
    // The same in one dimension, over [0,1).
    float get_1d(std::uint64_t pixel, std::uint32_t index, std::uint32_t count,
                 std::uint32_t dimension) const {
        return get_1d(pattern_keys(pixel, dimension), index, count, dimension);
    }

    // The same from the pattern's keys, worked out once for all of a pixel's samples.
    PatternKeys pattern_keys(std::uint64_t pixel, std::uint32_t dimension) const;
    Point2 get_2d(const PatternKeys& keys, std::uint32_t index, std::uint32_t count,
                  std::uint32_t dimension) const {
        if (on_regular_pixel_grid(dimension, count)) return regular_pixel_position(index);
        return pattern_2d(keys, index, count, dimension);
    }
    // Whether get_2d() gives the regular sampler's pixel positions, which need no keys: Whitted's
    // eye rays ask for them every sample, and they are worked out here without the grid again.
    bool on_regular_pixel_grid(std::uint32_t dimension, std::uint32_t count) const {
        return kind_ == SamplerKind::regular && dimension == kPixelDimension &&
               count == std::uint32_t(spp_);
    }
    Point2 regular_pixel_position(std::uint32_t index) const {
        return {(float(index % pixel_columns_) + 0.5f) / float(pixel_columns_),
                (float(index / pixel_columns_) + 0.5f) / float(pixel_rows_)};
    }
    float get_1d(const PatternKeys& keys, std::uint32_t index, std::uint32_t count,
                 std::uint32_t dimension) const;

private:
    Point2 pattern_2d(const PatternKeys& keys, std::uint32_t index, std::uint32_t count,
                      std::uint32_t dimension) const;

    SamplerKind kind_;
    int spp_;
    std::uint64_t seed_;
    std::uint64_t seed_key_;  // the seed's part of every pattern's key
    // The grid of the regular pixel positions, worked out once.
    std::uint32_t pixel_columns_, pixel_rows_;
};

// One pixel's pattern keys, each worked out when a sample first asks for it and kept for the
// pixel's other samples: hashing them is much of what a sample's numbers cost. Not thread-safe:
// one per pixel being rendered.
class PixelPatterns {
public:
    PixelPatterns(const Sampler& sampler, std::uint64_t pixel)
        : sampler_(&sampler), pixel_(pixel) {}

    const Sampler& sampler() const { return *sampler_; }
    std::uint64_t pixel() const { return pixel_; }

    PatternKeys keys(std::uint32_t dimension) {
        if (dimension >= kKept) return sampler_->pattern_keys(pixel_, dimension);
        const std::uint32_t bit = std::uint32_t(1) << dimension;
        if (!(known_ & bit)) {
            keys_[dimension] = sampler_->pattern_keys(pixel_, dimension);
            known_ |= bit;
        }
        return keys_[dimension];
    }

private:
    static constexpr std::uint32_t kKept = 32;  // the first dimensions: all that most samples use

    const Sampler* sampler_;
    std::uint64_t pixel_;
    std::uint32_t known_ = 0;  // bit d: keys_[d] is worked out
    std::array<PatternKeys, kKept> keys_;
};

// One sample of one pixel: the camera's dimensions, and fresh dimensions handed out in the order
// an integrator asks for them. Cheap to copy; allocates nothing.
class SampleStream {
public:
    // With the pixel's kept keys (the render loop), or working out each key anew.
    SampleStream(PixelPatterns& pixel, std::uint32_t index)
        : sampler_(&pixel.sampler()), pixel_(pixel.pixel()), patterns_(&pixel), index_(index) {}
    SampleStream(const Sampler& sampler, std::uint64_t pixel, std::uint32_t index)
        : sampler_(&sampler), pixel_(pixel), index_(index) {}

    std::uint32_t index() const { return index_; }

    // A reserved dimension (kPixelDimension, ...) of this sample.
    Point2 get_2d(std::uint32_t dimension) const { return get_2d(dimension, 0, 1); }
    float get_1d(std::uint32_t dimension) const {
        return sampler_->get_1d(keys(dimension), index_, spp(), dimension);
    }
    // Sub-sample j of n in one dimension (see Sampler::get_2d).
    Point2 get_2d(std::uint32_t dimension, std::uint32_t j, std::uint32_t n) const {
        const std::uint32_t index = index_ * n + j, count = spp() * n;
        if (sampler_->on_regular_pixel_grid(dimension, count))
            return sampler_->regular_pixel_position(index);  // without working out keys
        return sampler_->get_2d(keys(dimension), index, count, dimension);
    }

    // A dimension of its own for the caller, different from every other one of this sample.
    std::uint32_t next_dimension() { return next_++; }
    Point2 next_2d() { return get_2d(next_dimension()); }
    float next_1d() { return get_1d(next_dimension()); }

private:
    std::uint32_t spp() const { return std::uint32_t(sampler_->samples_per_pixel()); }
    PatternKeys keys(std::uint32_t dimension) const {
        return patterns_ ? patterns_->keys(dimension) : sampler_->pattern_keys(pixel_, dimension);
    }

    const Sampler* sampler_;
    std::uint64_t pixel_;
    PixelPatterns* patterns_ = nullptr;
    std::uint32_t index_;
    std::uint32_t next_ = kFirstFreeDimension;
};

}  // namespace glint
