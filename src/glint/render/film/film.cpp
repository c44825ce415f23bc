// Splatting samples through the reconstruction filter into fixed-point sums, and resolving them.
#include "glint/render/film/film.h"

#include <cmath>

namespace glint {

namespace {

constexpr double kFixedOne = 0x1p32;

// The product of a float weight and a float value is exact in double (24 + 24 bits < 53), and
// its rounding to the fixed-point unit depends on nothing else: the same sample adds the same
// integer wherever and whenever it is added. Rounded half away from zero by hand: |x| < 2^62
// (weights <= 1, valid samples < 2^30), and std::llrint is a library call in every sample.
FixedSum to_fixed(float weight, float value) {
    const double x = double(weight) * double(value) * kFixedOne;
    return FixedSum(std::int64_t(x + (x >= 0 ? 0.5 : -0.5)));
}

void add(PixelSum& sum, float weight, Color c) {
    sum.r += to_fixed(weight, c.r);
    sum.g += to_fixed(weight, c.g);
    sum.b += to_fixed(weight, c.b);
    sum.weight += to_fixed(weight, 1);
}

// The pixels along one axis whose centres i + 1/2 lie within the filter's support around the
// sample coordinate p: -radius < i + 1/2 - p <= radius (the box's own convention; the other
// filters are 0 at the edge anyway).
struct Span {
    int first, last;  // inclusive
};

Span reach(float p, float radius) {
    return {int(std::floor(p - 0.5f - radius)) + 1, int(std::floor(p - 0.5f + radius))};
}

}  // namespace

void BadSamples::add(SampleLocation where) {
    ++count;
    if (!first || where < *first) first = where;
}

BadSamples& BadSamples::operator+=(const BadSamples& o) {
    count += o.count;
    if (o.first && (!first || *o.first < *first)) first = o.first;
    return *this;
}

FilmTile::FilmTile(const Tile& tile, int image_width, int image_height, const Filter& filter,
                   bool importance_sampled)
    : filter_(&filter), one_pixel_(importance_sampled || is_one_pixel_box(filter.spec())) {
    if (one_pixel_) {
        region_ = tile;
        box_sums_.resize(std::size_t(width()) * std::size_t(region_.y1 - region_.y0));
        return;
    }
    const float r = filter.radius();
    const Span x = {reach(float(tile.x0), r).first, reach(float(tile.x1), r).last};
    const Span y = {reach(float(tile.y0), r).first, reach(float(tile.y1), r).last};
    region_ = {std::max(x.first, 0), std::max(y.first, 0), std::min(x.last + 1, image_width),
               std::min(y.last + 1, image_height)};
    sums_.resize(std::size_t(width()) * std::size_t(region_.y1 - region_.y0));
}

void FilmTile::splat(Point2 p, Color c) {
    const float r = filter_->radius();
    const Span xs = reach(p.x, r), ys = reach(p.y, r);
    const int x0 = std::max(xs.first, region_.x0), x1 = std::min(xs.last, region_.x1 - 1);
    const int y0 = std::max(ys.first, region_.y0), y1 = std::min(ys.last, region_.y1 - 1);
    float wx[kMaxFilterReach];
    for (int x = x0; x <= x1; ++x) wx[x - x0] = filter_->evaluate(float(x) + 0.5f - p.x);
    for (int y = y0; y <= y1; ++y) {
        const float wy = filter_->evaluate(float(y) + 0.5f - p.y);
        if (wy == 0) continue;
        PixelSum* row = sums_.data() + std::size_t(y - region_.y0) * width();
        for (int x = x0; x <= x1; ++x)
            if (wx[x - x0] != 0) add(row[x - region_.x0], wx[x - x0] * wy, c);
    }
}

SampleFootprint FilmTile::footprint(Point2 p) const {
    SampleFootprint f;
    f.p = p;
    if (one_pixel_) return f;
    const float r = filter_->radius();
    const Span xs = reach(p.x, r), ys = reach(p.y, r);
    f.x0 = std::max(xs.first, region_.x0), f.x1 = std::min(xs.last, region_.x1 - 1);
    f.y0 = std::max(ys.first, region_.y0), f.y1 = std::min(ys.last, region_.y1 - 1);
    for (int x = f.x0; x <= f.x1; ++x)
        f.wx[std::size_t(x - f.x0)] = filter_->evaluate(float(x) + 0.5f - p.x);
    for (int y = f.y0; y <= f.y1; ++y)
        f.wy[std::size_t(y - f.y0)] = filter_->evaluate(float(y) + 0.5f - p.y);
    return f;
}

void FilmTile::add_weighted(const SampleFootprint& f, Color c) {
    for (int y = f.y0; y <= f.y1; ++y) {
        const float wy = f.wy[std::size_t(y - f.y0)];
        if (wy == 0) continue;
        PixelSum* row = sums_.data() + std::size_t(y - region_.y0) * width();
        for (int x = f.x0; x <= f.x1; ++x) {
            const float wx = f.wx[std::size_t(x - f.x0)];
            if (wx != 0) add(row[x - region_.x0], wx * wy, c);
        }
    }
}

namespace {

// The ratio of the sums, also when the weights sum below zero (a few samples in a filter's
// negative lobes): only weights that cancel leave nothing to divide by.
Color resolved(const PixelSum& s) {
    if (s.weight == 0) return {};
    const double w = double(s.weight);
    return {float(double(s.r) / w), float(double(s.g) / w), float(double(s.b) / w)};
}

}  // namespace

Film::Film(int width, int height, const FilterSpec& filter, bool importance_sampled)
    : width_(width),
      height_(height),
      filter_(filter),
      importance_sampled_(importance_sampled),
      one_pixel_(importance_sampled || is_one_pixel_box(filter)) {
    if (one_pixel_) {
        box_sums_.resize(std::size_t(width) * height);
    } else {
        sums_.resize(std::size_t(width) * height);
    }
}

FilmTile Film::make_tile(const Tile& tile) const {
    FilmTile film_tile(tile, width_, height_, filter_, importance_sampled_);
    if (one_pixel_) {
        const Tile& r = film_tile.region();
        for (int y = r.y0; y < r.y1; ++y)
            for (int x = r.x0; x < r.x1; ++x)
                film_tile.box_sums_[film_tile.index(x, y)] = box_sums_[std::size_t(y) * width_ + x];
    }
    return film_tile;
}

void Film::merge(const FilmTile& tile) {
    const Tile& r = tile.region();
    if (one_pixel_) {
        // No other tile's samples reach these pixels: the tile's sums replace the film's, which
        // they started from, and need no lock.
        for (int y = r.y0; y < r.y1; ++y)
            for (int x = r.x0; x < r.x1; ++x)
                box_sums_[std::size_t(y) * width_ + x] = tile.box_at(x, y);
        return;
    }
    const std::lock_guard lock(*merge_mutex_);
    for (int y = r.y0; y < r.y1; ++y)
        for (int x = r.x0; x < r.x1; ++x) {
            PixelSum& sum = sums_[std::size_t(y) * width_ + x];
            const PixelSum& add = tile.at(x, y);
            sum.r += add.r;
            sum.g += add.g;
            sum.b += add.b;
            sum.weight += add.weight;
        }
}

Image Film::resolve() const {
    Image image(width_, height_);
    if (one_pixel_) {
        // As resolved(): importance-sampled filters weigh samples in negative lobes below zero.
        for (std::size_t i = 0; i < box_sums_.size(); ++i)
            if (const BoxSum& s = box_sums_[i]; s.weight != 0) image.pixels[i] = s.sum / s.weight;
        return image;
    }
    for (std::size_t i = 0; i < sums_.size(); ++i) image.pixels[i] = resolved(sums_[i]);
    return image;
}

}  // namespace glint
