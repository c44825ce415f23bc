// Splatting particles: the filter's weights over the pixels a position reaches, each divided by
// the filter's integral over the image for that pixel, rounded to fixed point and added.
#include "glint/render/film/splat_film.h"

#include <cmath>

namespace glint {

namespace {

constexpr double kUnit = 0x1p24;

// The integral of the filter over [0, extent) around a pixel centre at c, by the midpoint rule
// on 64 steps a pixel: the filters are smooth enough, and exact for the box.
std::vector<float> norms(const Filter& filter, int extent) {
    const float r = filter.radius();
    const int steps = 64;
    std::vector<float> out(static_cast<std::size_t>(extent));
    for (int i = 0; i < extent; ++i) {
        const double c = i + 0.5;
        double sum = 0;
        const int first = std::max(0, int(std::floor((c - r) * steps)));
        const int last = std::min(extent * steps, int(std::ceil((c + r) * steps)));
        for (int k = first; k < last; ++k) sum += filter.evaluate(float((k + 0.5) / steps - c));
        out[std::size_t(i)] = float(sum / steps);
    }
    return out;
}

}  // namespace

SplatFilm::SplatFilm(int width, int height, const FilterSpec& filter)
    : width_(width),
      height_(height),
      filter_(filter),
      column_norm_(norms(filter_, width)),
      row_norm_(norms(filter_, height)),
      sums_(std::make_unique<std::vector<std::atomic<std::int64_t>>>(std::size_t(width) *
                                                                     std::size_t(height) * 3)) {}

void SplatFilm::splat(Point2 p, Color c) {
    if (!(p.x >= 0 && p.x < float(width_) && p.y >= 0 && p.y < float(height_))) return;
    const float r = filter_.radius();
    // The pixels whose centres lie within the radius: -r < i + 1/2 - p <= r.
    const int x0 = std::max(0, int(std::floor(p.x - 0.5f - r)) + 1);
    const int x1 = std::min(width_ - 1, int(std::floor(p.x - 0.5f + r)));
    const int y0 = std::max(0, int(std::floor(p.y - 0.5f - r)) + 1);
    const int y1 = std::min(height_ - 1, int(std::floor(p.y - 0.5f + r)));
    for (int y = y0; y <= y1; ++y) {
        const float wy = filter_.evaluate(float(y) + 0.5f - p.y) / row_norm_[std::size_t(y)];
        if (wy == 0) continue;
        for (int x = x0; x <= x1; ++x) {
            const float w =
                wy * filter_.evaluate(float(x) + 0.5f - p.x) / column_norm_[std::size_t(x)];
            if (w == 0) continue;
            std::atomic<std::int64_t>* s = sums_->data() + (std::size_t(y) * width_ + x) * 3;
            const auto add = [&](std::atomic<std::int64_t>& sum, float v) {
                sum.fetch_add(std::int64_t(std::llround(double(w) * double(v) * kUnit)),
                              std::memory_order_relaxed);
            };
            add(s[0], c.r);
            add(s[1], c.g);
            add(s[2], c.b);
        }
    }
}

float SplatFilm::weight(Point2 p, int x, int y) const {
    if (!(p.x >= 0 && p.x < float(width_) && p.y >= 0 && p.y < float(height_))) return 0;
    if (x < 0 || x >= width_ || y < 0 || y >= height_) return 0;
    const float r = filter_.radius();
    const float dx = float(x) + 0.5f - p.x, dy = float(y) + 0.5f - p.y;
    // As splat: the pixels whose centres lie within -r < d <= r.
    if (!(dx > -r && dx <= r && dy > -r && dy <= r)) return 0;
    return filter_.evaluate(dy) / row_norm_[std::size_t(y)] *
           (filter_.evaluate(dx) / column_norm_[std::size_t(x)]);
}

Image SplatFilm::resolve(float scale) const {
    Image image(width_, height_);
    const double factor = double(scale) / kUnit;
    for (std::size_t i = 0; i < image.pixels.size(); ++i) {
        const auto& s = *sums_;
        image.pixels[i] = {float(double(s[3 * i].load()) * factor),
                           float(double(s[3 * i + 1].load()) * factor),
                           float(double(s[3 * i + 2].load()) * factor)};
    }
    return image;
}

std::vector<std::int64_t> SplatFilm::sums() const {
    std::vector<std::int64_t> out(sums_->size());
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = (*sums_)[i].load();
    return out;
}

void SplatFilm::set_sums(const std::vector<std::int64_t>& sums) {
    for (std::size_t i = 0; i < sums.size() && i < sums_->size(); ++i) (*sums_)[i] = sums[i];
}

}  // namespace glint
