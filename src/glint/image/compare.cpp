// Image comparison metrics for golden-image tests.
#include "glint/image/compare.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "glint/image/image_error.h"
#include "glint/image/srgb.h"

namespace glint {
namespace {

void check_same_size(const Image& a, const Image& b) {
    if (a.width != b.width || a.height != b.height || a.pixels.size() != b.pixels.size()) {
        throw ImageError("cannot compare images of different sizes: " + std::to_string(a.width) +
                         "x" + std::to_string(a.height) + " and " + std::to_string(b.width) + "x" +
                         std::to_string(b.height));
    }
}

double channel_difference(float a, float b) {
    if (std::isnan(a) || std::isnan(b)) return std::isnan(a) && std::isnan(b) ? 0 : 1;
    return std::abs(double(linear_to_srgb(a)) - double(linear_to_srgb(b)));
}

}  // namespace

ImageDifference compare_images(const Image& a, const Image& b, double threshold) {
    check_same_size(a, b);
    ImageDifference result;
    result.width = a.width;
    result.height = a.height;
    result.threshold = threshold;
    if (a.pixels.empty()) return result;

    double sum_squares = 0;
    std::size_t over = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        const Color& p = a.pixels[i];
        const Color& q = b.pixels[i];
        const double d[3] = {channel_difference(p.r, q.r), channel_difference(p.g, q.g),
                             channel_difference(p.b, q.b)};
        const double largest = std::max({d[0], d[1], d[2]});
        sum_squares += d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
        result.max_abs = std::max(result.max_abs, largest);
        if (largest > threshold) ++over;
    }
    result.rmse = std::sqrt(sum_squares / double(3 * a.pixels.size()));
    result.fraction_over_threshold = double(over) / double(a.pixels.size());
    return result;
}

Image difference_image(const Image& a, const Image& b) {
    check_same_size(a, b);
    Image result(a.width, a.height);
    const auto shown = [](float p, float q) {
        return srgb_to_linear(float(std::min(1.0, 4 * channel_difference(p, q))));
    };
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        const Color& p = a.pixels[i];
        const Color& q = b.pixels[i];
        result.pixels[i] = {shown(p.r, q.r), shown(p.g, q.g), shown(p.b, q.b)};
    }
    return result;
}

std::string describe(const ImageDifference& d) {
    const double pixels = double(d.width) * double(d.height);
    char text[256];
    std::snprintf(text, sizeof text,
                  "%dx%d pixels: rmse %.4g (%.2f/255), max %.4g (%.1f/255), %.2f%% of pixels "
                  "(%.0f) differ by more than %.4g (%.1f/255)",
                  d.width, d.height, d.rmse, d.rmse * 255, d.max_abs, d.max_abs * 255,
                  d.fraction_over_threshold * 100, std::round(d.fraction_over_threshold * pixels),
                  d.threshold, d.threshold * 255);
    return text;
}

}  // namespace glint
