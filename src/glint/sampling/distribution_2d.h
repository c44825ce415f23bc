// Picking a point of [0,1)^2 with a density proportional to a grid of weights, piecewise constant
// over its cells: a row by the rows' sums, then a column within it (pbrt's Distribution2D). What
// an image sky is importance-sampled with, its pixels weighted by brightness.
#pragma once

#include <cstddef>
#include <vector>

#include "glint/math/vector.h"
#include "glint/sampling/discrete_distribution.h"

namespace glint {

class Distribution2D {
public:
    // weights: width x height non-negative values, row by row, not all zero.
    Distribution2D(const std::vector<float>& weights, int width, int height);

    // A point drawn from u, and its density per unit area of [0,1)^2.
    Point2 sample(Point2 u, float* pdf) const;
    float pdf(Point2 p) const;

private:
    int width_, height_;
    std::vector<DiscreteDistribution> rows_;  // a column within each row
    DiscreteDistribution marginal_;           // a row, by the rows' sums
};

}  // namespace glint
