// Picking one of n items with probability proportional to a weight, e.g. a mesh's triangle by
// its area so that points on the mesh come out uniform by area.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

namespace glint {

// A discrete distribution over indices 0..n-1 with P(i) = w_i / sum of w, sampled by binary
// search over its cumulative distribution. Immutable after construction.
class DiscreteDistribution {
public:
    // Weights must be finite and non-negative with at least one positive; throws
    // std::invalid_argument otherwise (empty, all zero, negative, NaN or infinite).
    explicit DiscreteDistribution(std::span<const float> weights);

    // The index i with cdf(i) <= u < cdf(i + 1), so item i comes with probability
    // probability(i) and an item of weight 0 never does. u in [0, 1); values outside are
    // clamped. If `remapped` is given it receives u re-stretched to [0, 1) within the chosen
    // item's interval: uniform and independent of the choice, so it can drive a further warp.
    std::size_t sample(float u, float* remapped = nullptr) const;

    // w_i / sum of w.
    float probability(std::size_t i) const { return float(double(weights_[i]) / total_); }
    // The sum of the weights.
    float total() const { return float(total_); }
    std::size_t size() const { return weights_.size(); }

private:
    std::vector<float> weights_;
    // cdf_[i] = (w_0 + ... + w_{i-1}) / total, summed in double; cdf_[0] = 0, cdf_.back() = 1.
    std::vector<double> cdf_;
    double total_ = 0;
};

}  // namespace glint
