// The film of the light integrator's particles: each contribution is splatted where it lands,
// through the image's reconstruction filter normalised to integrate to 1 over the image, so that
// particles from any tile may reach any pixel. The sums are fixed point in 64-bit integers added
// atomically: integer addition does not care about order, so the image is the same bit for bit
// whatever thread or tile splats first.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <vector>

#include "glint/image/image.h"
#include "glint/math/color.h"
#include "glint/math/vector.h"
#include "glint/sampling/filter.h"

namespace glint {

class SplatFilm {
public:
    SplatFilm(int width, int height, const FilterSpec& filter);

    // Adds c at film position p (pixels), weighted by the filter over each pixel it reaches.
    // Positions outside the image add nothing. Thread-safe. c must be valid (is_valid_sample).
    void splat(Point2 p, Color c);
    // The weight with which splat(p, c) adds c to pixel (x, y): the filter's there over its
    // integral; 0 for a pixel beyond the filter's reach or a position outside the image.
    float weight(Point2 p, int x, int y) const;

    // The sums times scale (1 over the particles per pixel).
    Image resolve(float scale) const;

    // The raw sums, three a pixel row by row, 2^-24 their unit: to save a render and continue it.
    std::vector<std::int64_t> sums() const;
    void set_sums(const std::vector<std::int64_t>& sums);
    std::size_t size() const { return sums_->size(); }
    // One raw sum, and set: not concurrent with splat().
    std::int64_t sum(std::size_t i) const { return (*sums_)[i].load(std::memory_order_relaxed); }
    void set_sum(std::size_t i, std::int64_t v) { (*sums_)[i].store(v, std::memory_order_relaxed); }

private:
    int width_, height_;
    Filter filter_;
    // The filter's integral over the image along each axis for each pixel's centre, so that a
    // pixel by the edge, whose filter the image cuts, weighs what lands in it as much.
    std::vector<float> column_norm_, row_norm_;
    // Behind a pointer so that the film moves (atomics do not).
    std::unique_ptr<std::vector<std::atomic<std::int64_t>>> sums_;
};

}  // namespace glint
