// The film: accumulates each pixel's weighted samples and resolves them to an image. It also
// keeps the first non-finite sample, so that a NaN is reported, not painted.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "glint/image/image.h"
#include "glint/math/color.h"

namespace glint {

struct SampleLocation {
    int x = 0, y = 0, sample = 0;
    // Scanline order, so that "the first bad sample" does not depend on thread timing.
    bool operator<(const SampleLocation& o) const {
        return y != o.y ? y < o.y : x != o.x ? x < o.x : sample < o.sample;
    }
};

// Non-finite samples met while rendering; they are left out of the image.
struct BadSamples {
    std::uint64_t count = 0;
    std::optional<SampleLocation> first;

    void add(SampleLocation where);
    BadSamples& operator+=(const BadSamples& o);
};

// A box reconstruction filter over each pixel's own samples. Distinct pixels may be written
// from distinct threads concurrently.
class Film {
public:
    Film(int width, int height)
        : width_(width), height_(height), sum_(std::size_t(width) * height) {
        weight_.assign(sum_.size(), 0.0f);
    }

    int width() const { return width_; }
    int height() const { return height_; }

    // Adds a finite sample; a non-finite one is recorded in bad instead.
    void add_sample(SampleLocation where, Color c, BadSamples& bad);

    // Pixels without samples (an interrupted render) resolve to black.
    Image resolve() const;

private:
    int width_, height_;
    std::vector<Color> sum_;
    std::vector<float> weight_;
};

}  // namespace glint
