// The film's box-filtered accumulation of samples per pixel, with NaN and infinite samples left
// out and counted.
#include "glint/render/film.h"

namespace glint {

void BadSamples::add(SampleLocation where) {
    ++count;
    if (!first || where < *first) first = where;
}

BadSamples& BadSamples::operator+=(const BadSamples& o) {
    count += o.count;
    if (o.first && (!first || *o.first < *first)) first = o.first;
    return *this;
}

void Film::add_sample(SampleLocation where, Color c, BadSamples& bad) {
    if (!is_finite(c)) {
        bad.add(where);
        return;
    }
    const std::size_t i = std::size_t(where.y) * width_ + where.x;
    sum_[i] += c;
    weight_[i] += 1;
}

Image Film::resolve() const {
    Image image(width_, height_);
    for (std::size_t i = 0; i < sum_.size(); ++i)
        if (weight_[i] > 0) image.pixels[i] = sum_[i] / weight_[i];
    return image;
}

}  // namespace glint
