// The two-stage pick: the row's cell by the marginal, the column's by the row's conditional, each
// re-stretched number placing the point within its cell.
#include "glint/sampling/distribution_2d.h"

#include <algorithm>

namespace glint {

namespace {

std::vector<DiscreteDistribution> rows_of(const std::vector<float>& w, int width, int height) {
    std::vector<DiscreteDistribution> rows;
    rows.reserve(std::size_t(height));
    for (int y = 0; y < height; ++y) {
        std::vector<float> row(w.begin() + std::ptrdiff_t(y) * width,
                               w.begin() + std::ptrdiff_t(y + 1) * width);
        float sum = 0;
        for (const float v : row) sum += v;
        // A row of nothing is never picked; its own pick is then uniform, for the type's sake.
        if (!(sum > 0)) std::fill(row.begin(), row.end(), 1.0f);
        rows.emplace_back(row);
    }
    return rows;
}

std::vector<float> row_sums(const std::vector<float>& w, int width, int height) {
    std::vector<float> sums(std::size_t(height), 0);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) sums[std::size_t(y)] += w[std::size_t(y) * width + x];
    return sums;
}

}  // namespace

Distribution2D::Distribution2D(const std::vector<float>& weights, int width, int height)
    : width_(width),
      height_(height),
      rows_(rows_of(weights, width, height)),
      marginal_(row_sums(weights, width, height)) {}

Point2 Distribution2D::sample(Point2 u, float* pdf) const {
    float uy = 0, ux = 0;
    const std::size_t row = marginal_.sample(u.y, &uy);
    const std::size_t column = rows_[row].sample(u.x, &ux);
    const Point2 p{(float(column) + ux) / float(width_), (float(row) + uy) / float(height_)};
    if (pdf) *pdf = this->pdf(p);
    return p;
}

float Distribution2D::pdf(Point2 p) const {
    const auto row = std::size_t(std::clamp(int(p.y * float(height_)), 0, height_ - 1));
    const auto column = std::size_t(std::clamp(int(p.x * float(width_)), 0, width_ - 1));
    return marginal_.probability(row) * rows_[row].probability(column) * float(width_) *
           float(height_);
}

}  // namespace glint
