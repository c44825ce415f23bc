// DiscreteDistribution: a cumulative table in double, so that a million small triangle areas
// sum without the drift a float running sum would have.
#include "glint/sampling/discrete_distribution.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace glint {

DiscreteDistribution::DiscreteDistribution(std::span<const float> weights)
    : weights_(weights.begin(), weights.end()) {
    if (weights_.empty()) throw std::invalid_argument("DiscreteDistribution: no weights");
    cdf_.resize(weights_.size() + 1);
    cdf_[0] = 0;
    for (std::size_t i = 0; i < weights_.size(); ++i) {
        const float w = weights_[i];
        if (!std::isfinite(w) || w < 0) {
            throw std::invalid_argument("DiscreteDistribution: weight " + std::to_string(i) +
                                        " is " + std::to_string(w) +
                                        "; weights must be finite and non-negative");
        }
        cdf_[i + 1] = cdf_[i] + double(w);
    }
    total_ = cdf_.back();
    if (!(total_ > 0)) {
        throw std::invalid_argument("DiscreteDistribution: all weights are zero");
    }
    // Dividing by the same positive total keeps the table non-decreasing; the last entry is
    // exactly 1, so every u < 1 finds an interval.
    for (double& c : cdf_) c /= total_;
    cdf_.back() = 1;
}

std::size_t DiscreteDistribution::sample(float u, float* remapped) const {
    const double x = std::clamp(double(u), 0.0, std::nextafter(1.0, 0.0));
    // The first entry above x ends the chosen interval; an interval of zero width (an item of
    // weight 0) can never be the one whose start is <= x < its end.
    const auto end = std::upper_bound(cdf_.begin() + 1, cdf_.end(), x);
    const auto i = std::size_t(end - (cdf_.begin() + 1));
    if (remapped) {
        const double r = (x - cdf_[i]) / (cdf_[i + 1] - cdf_[i]);
        *remapped = std::min(float(r), 0x1.fffffep-1f);
    }
    return i;
}

}  // namespace glint
