// Filter importance sampling (Ernst, Stamminger and Greiner 2006): a pixel's sample positions
// drawn with density proportional to |filter|, so that each sample counts for its own pixel only,
// weighted by the filter over that density. Adaptive sampling needs it: a pixel's value then
// depends on its own samples alone, however many its neighbours took.
#pragma once

#include <vector>

#include "glint/math/vector.h"
#include "glint/sampling/discrete_distribution.h"
#include "glint/sampling/filter.h"

namespace glint {

// A sample's place and weight: the position from the pixel's corner (in [1/2 - r, 1/2 + r] on
// each axis, so beyond the pixel and the image's edge), and f(x) f(y) over the density it was
// drawn with, up to a constant: 1 for the box, within a ulp or so of 1 for the tent, close to
// 1 for the Gaussian and ±1 (negative in its lobes) for Mitchell's cubic.
struct FilterSample {
    Point2 position;
    float weight = 1;
};

class FilterSampling {
public:
    explicit FilterSampling(const FilterSpec& spec);

    // The sample that the pixel-dimension numbers u in [0,1)^2 give. For the box the position
    // is 1/2 - r + 2 r u exactly (u itself for the one-pixel box).
    FilterSample sample(Point2 u) const;

    // The density along one axis at offset x from the pixel's centre, integrating to 1 over
    // [-r, r]: piecewise linear through |f| at knots 1/64 pixel apart (exact for box and tent).
    float pdf(float x) const;

private:
    // An offset from the centre, and its weight along that axis (not for the box).
    float sample_1d(float u, float* weight) const;

    Filter filter_;
    float step_ = 0;               // between knots, in pixels
    std::vector<float> knots_;     // |f| at -r, -r + step, ..., r
    DiscreteDistribution pieces_;  // each piece's area under the linear interpolant
};

}  // namespace glint
