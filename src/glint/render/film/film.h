// The film: every pixel's sum of filter-weighted samples, its own and its neighbours' across
// pixel and tile borders, resolved to an image. The sums are kept in fixed point, so that adding
// is exact and the image is the same bit for bit whatever order the tiles, threads, passes or
// machines add their samples in. A box of radius 1/2 (Whitted's film) keeps each sample in its
// own pixel, whose samples all arrive from one tile in sample order, pass after pass: plain float
// sums are as deterministic there, and cheaper. So does filter importance sampling (adaptive
// sampling's film, filter_sampling.h): the filter shapes where a pixel's samples are taken and
// how much each weighs, and each sample counts for its own pixel alone.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

#include "glint/image/image.h"
#include "glint/math/color.h"
#include "glint/math/vector.h"
#include "glint/render/tiles.h"
#include "glint/sampling/filter.h"

namespace glint {

struct SampleLocation {
    int x = 0, y = 0, sample = 0;
    // Scanline order, so that "the first bad sample" does not depend on thread timing.
    bool operator<(const SampleLocation& o) const {
        return y != o.y ? y < o.y : x != o.x ? x < o.x : sample < o.sample;
    }
};

// Samples left out of the image: NaN, infinite, or beyond kMaxSampleValue.
struct BadSamples {
    std::uint64_t count = 0;
    std::optional<SampleLocation> first;

    void add(SampleLocation where);
    BadSamples& operator+=(const BadSamples& o);
};

// The brightest channel value a sample may have: fixed-point sums hold 32 fractional bits in a
// 64-bit product of weight and value. A brighter sample is treated as a non-finite one.
inline constexpr float kMaxSampleValue = 0x1p30f;

// Whether a sample may enter the film: finite, no channel beyond kMaxSampleValue either way.
inline bool is_valid_sample(Color c) {
    return std::abs(c.r) < kMaxSampleValue && std::abs(c.g) < kMaxSampleValue &&
           std::abs(c.b) < kMaxSampleValue;  // false for NaN too
}

// An exact sum of weighted channel values, 2^-32 its unit.
__extension__ using FixedSum = __int128;

struct PixelSum {
    FixedSum r = 0, g = 0, b = 0, weight = 0;
};

// A pixel's sum of its own samples (the one-pixel box, filter importance sampling): the
// weighted samples, added in sample order, and the sum of their weights (their count under the
// box, whose weights are 1).
struct BoxSum {
    Color sum;
    float weight = 0;
};

// The most pixels a sample reaches along one axis.
inline constexpr int kMaxFilterReach = 2 * int(kMaxFilterRadius) + 1;

// Where a sample lands and its filter weights over the pixels it reaches: worked out once, it
// adds the sample to several films of one filter and tile (the output variables') as
// add_sample(p, c) adds it to one.
struct SampleFootprint {
    Point2 p;
    int x0 = 0, x1 = -1, y0 = 0, y1 = -1;       // the pixels reached within the tile, inclusive
    std::array<float, kMaxFilterReach> wx, wy;  // from x0 and y0 on; the rest is not set
};

// One tile's private part of the film: the pixels its samples reach, which extend past the tile
// by the filter's radius. A render thread fills it without locks; Film::merge adds it in. Under
// the one-pixel box it starts from the film's running sums of its pixels (Film::make_tile), so
// that each pixel's float additions happen in sample order across passes.
class FilmTile {
public:
    // With importance_sampled, samples are added to their own pixels with add_to_pixel.
    FilmTile(const Tile& tile, int image_width, int image_height, const Filter& filter,
             bool importance_sampled = false);

    // Adds sample c taken at film position p (pixels; p is inside the tile) to every pixel whose
    // centre lies within the filter's radius, weighted by the filter. c must be valid
    // (is_valid_sample).
    void add_sample(Point2 p, Color c) {
        if (!one_pixel_) return splat(p, c);
        // The general path's result for this filter: the one pixel whose span (i - 1/2, i + 1/2]
        // holds p - 1/2 is floor(p), which truncation gives as film positions are not negative
        // (clamped: a jittered offset may round up to the next pixel's edge).
        const int x = std::min(int(p.x), region_.x1 - 1), y = std::min(int(p.y), region_.y1 - 1);
        BoxSum& s = box_sums_[std::size_t(y - region_.y0) * width() + std::size_t(x - region_.x0)];
        s.sum += c;
        s.weight += 1;
    }

    // Adds sample c of pixel (x, y) (in the tile), drawn by filter importance sampling, to that
    // pixel alone with its weight.
    void add_to_pixel(int x, int y, float weight, Color c) {
        BoxSum& s = box_sums_[index(x, y)];
        s.sum += c * weight;
        s.weight += weight;
    }

    // The footprint of a sample at p, and the sample added through one: the same sums as
    // add_sample(p, c).
    SampleFootprint footprint(Point2 p) const;
    void add_sample_through(const SampleFootprint& f, Color c) {
        if (one_pixel_) return add_sample(f.p, c);
        add_weighted(f, c);
    }

    const Tile& region() const { return region_; }  // pixels covered, clipped to the image
    // A pixel's sums: box_at for the one-pixel box, at for every other filter.
    const PixelSum& at(int x, int y) const { return sums_[index(x, y)]; }
    const BoxSum& box_at(int x, int y) const { return box_sums_[index(x, y)]; }

private:
    friend class Film;  // starts a one-pixel tile from the film's sums
    int width() const { return region_.x1 - region_.x0; }
    std::size_t index(int x, int y) const {
        return std::size_t(y - region_.y0) * width() + std::size_t(x - region_.x0);
    }
    // The image's path, evaluating the weights as it adds (measured faster than through a
    // footprint, bench/README.md#output-variables).
    void splat(Point2 p, Color c);
    void add_weighted(const SampleFootprint& f, Color c);

    const Filter* filter_;
    // A box of radius 1/2 (each sample adds to its own pixel with weight 1), or filter
    // importance sampling (add_to_pixel).
    bool one_pixel_;
    Tile region_;  // the tile itself for one_pixel_
    std::vector<PixelSum> sums_;
    std::vector<BoxSum> box_sums_;  // instead of sums_ for one_pixel_
};

class Film {
public:
    // The spec must be valid (describe_problem(spec) is empty). importance_sampled: the samples
    // are drawn by filter importance sampling and added each to its own pixel (add_to_pixel).
    Film(int width, int height, const FilterSpec& filter, bool importance_sampled = false);

    int width() const { return width_; }
    int height() const { return height_; }
    const Filter& filter() const { return filter_; }
    bool importance_sampled() const { return importance_sampled_; }
    // A box of radius 1/2, or importance sampled: the film keeps box_sums(), not sums().
    bool one_pixel() const { return one_pixel_; }

    // A tile to fill; for the one-pixel box it holds the film's sums of its pixels so far.
    // Concurrent with merges of other tiles only for the one-pixel box (tiles share no pixels).
    FilmTile make_tile(const Tile& tile) const;
    // Adds a finished tile's sums. Thread-safe; the order of merges does not matter.
    void merge(const FilmTile& tile);

    // Each pixel's weighted sum over its sum of weights; black where no weight arrived (pixels
    // of an interrupted render). Not concurrent with merge().
    Image resolve() const;

    // Every pixel's sums, row by row, to save a render and continue it (render_state.h).
    std::vector<PixelSum>& sums() { return sums_; }
    const std::vector<PixelSum>& sums() const { return sums_; }
    std::vector<BoxSum>& box_sums() { return box_sums_; }
    const std::vector<BoxSum>& box_sums() const { return box_sums_; }

private:
    int width_, height_;
    Filter filter_;
    bool importance_sampled_;
    // A box of radius 1/2 or filter importance sampling keeps each sample in its own pixel, so
    // tiles never share pixels: its float sums (16 bytes a pixel) need no lock, and the
    // fixed-point film of sums (64 bytes a pixel) is never built.
    bool one_pixel_;
    std::vector<PixelSum> sums_;
    std::vector<BoxSum> box_sums_;  // instead of sums_ for one_pixel_
    // Behind a pointer so that a Film moves (a RenderState holds one).
    std::unique_ptr<std::mutex> merge_mutex_ = std::make_unique<std::mutex>();
};

}  // namespace glint
