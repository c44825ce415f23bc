// Filter importance sampling: a piece of the piecewise-linear |f| chosen by its area, then the
// point inside it by inverting the linear density's cumulative distribution in closed form.
#include "glint/sampling/filter_sampling.h"

#include <algorithm>
#include <cmath>

namespace glint {

namespace {

// Knots per pixel of radius: fine enough that the Gaussian's weights stay within a percent of
// 1, and a multiple of 2 so that 0 and Mitchell's kink at r/2 are knots.
constexpr int kKnotsPerPixel = 64;

int half_pieces(float radius) { return kKnotsPerPixel * int(std::ceil(radius)); }

std::vector<float> knots_of(const Filter& filter) {
    const int half = half_pieces(filter.radius());
    const double step = double(filter.radius()) / half;
    std::vector<float> knots(std::size_t(2 * half + 1));
    for (int i = -half; i <= half; ++i)
        knots[std::size_t(i + half)] = std::abs(filter.evaluate(float(i * step)));
    // The box is 0 at -r by its one-sided convention, but its density is flat.
    if (filter.spec().kind == FilterKind::box) knots.front() = knots.back() = 1;
    return knots;
}

std::vector<float> piece_areas(const std::vector<float>& knots) {
    std::vector<float> areas(knots.size() - 1);
    for (std::size_t i = 0; i + 1 < knots.size(); ++i) areas[i] = knots[i] + knots[i + 1];
    return areas;
}

}  // namespace

FilterSampling::FilterSampling(const FilterSpec& spec)
    : filter_(spec),
      step_(spec.radius / float(half_pieces(spec.radius))),
      knots_(knots_of(filter_)),
      pieces_(piece_areas(knots_)) {}

// Not for the box, whose density is flat.
float FilterSampling::sample_1d(float u, float* weight) const {
    float v = 0;
    const std::size_t i = pieces_.sample(u, &v);
    const float a = knots_[i], b = knots_[i + 1];
    // The linear density a + (b - a) t on [0, 1) has the cumulative a t + (b - a) t^2 / 2, which
    // is v (a + b) / 2 at t = v (a + b) / (a + sqrt(a^2 + (b^2 - a^2) v)): no cancellation when
    // a and b are close, and sqrt(v) when a is 0.
    const float root = std::sqrt(std::max(0.0f, a * a + (b * b - a * a) * v));
    const float t = std::min(a + root > 0 ? v * (a + b) / (a + root) : v, 0x1.fffffep-1f);
    const float x = -filter_.radius() + (float(i) + t) * step_;
    const float density = a + (b - a) * t;  // |f| as tabulated, at x
    *weight = density > 0 ? filter_.evaluate(x) / density : 0;
    return x;
}

FilterSample FilterSampling::sample(Point2 u) const {
    const float r = filter_.radius();
    if (filter_.spec().kind == FilterKind::box) {
        // u itself for the one-pixel box: the position a splatted render takes.
        return {{2 * r * u.x + (0.5f - r), 2 * r * u.y + (0.5f - r)}, 1};
    }
    float wx = 0, wy = 0;
    const float x = sample_1d(u.x, &wx), y = sample_1d(u.y, &wy);
    return {{0.5f + x, 0.5f + y}, wx * wy};
}

float FilterSampling::pdf(float x) const {
    const float r = filter_.radius();
    if (!(std::abs(x) <= r)) return 0;
    if (filter_.spec().kind == FilterKind::box) return 1 / (2 * r);
    const float s = (x + r) / step_;
    const std::size_t i = std::min(std::size_t(s), knots_.size() - 2);
    const float t = s - float(i);
    // Each piece's area is step (a + b) / 2; pieces_.total() sums a + b.
    return (knots_[i] + (knots_[i + 1] - knots_[i]) * t) / (pieces_.total() * step_ / 2);
}

}  // namespace glint
