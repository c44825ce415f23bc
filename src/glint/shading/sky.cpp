// Directions and the image's (u, v): u = 1/2 + atan2(-x, z) / 2 pi, v = theta / pi with
// cos(theta) = y, so a pixel row spans a band of solid angle (2 pi / width)(cos theta_0 -
// cos theta_1) per pixel, and a density over (u, v) is one over the sphere divided by
// 2 pi^2 sin(theta).
#include "glint/shading/sky.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "glint/math/constants.h"
#include "glint/sampling/warp.h"

namespace glint {

namespace {

Point2 image_uv(Vector3 w) {
    const float phi = std::atan2(-w.x, w.z);
    const float theta = std::acos(std::clamp(w.y, -1.0f, 1.0f));
    return {0.5f + phi / (2 * kPi), theta / kPi};
}

Vector3 image_direction(Point2 uv, float* sin_theta) {
    const float phi = (uv.x - 0.5f) * 2 * kPi, theta = uv.y * kPi;
    const float s = std::sin(theta);
    *sin_theta = s;
    return {-s * std::sin(phi), std::cos(theta), s * std::cos(phi)};
}

// The pixel, its scale applied, at column x (wrapping round) and row y (clamped at the poles).
Color pixel(const SkyImage& sky, int x, int y) {
    const Image& image = *sky.image;
    x %= image.width;
    if (x < 0) x += image.width;
    y = std::clamp(y, 0, image.height - 1);
    return image.at(x, y) * sky.scale;
}

std::shared_ptr<const Distribution2D> brightness_distribution(const SkyImage& sky) {
    const int width = sky.image->width, height = sky.image->height;
    std::vector<float> weights(std::size_t(width) * std::size_t(height));
    float total = 0;
    for (int y = 0; y < height; ++y) {
        const float sin_theta = std::sin((float(y) + 0.5f) / float(height) * kPi);
        for (int x = 0; x < width; ++x) {
            float brightest = 0;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx)
                    brightest = std::max(brightest, mean(pixel(sky, x + dx, y + dy)));
            const float w = brightest * sin_theta;
            weights[std::size_t(y) * std::size_t(width) + std::size_t(x)] = w;
            total += w;
        }
    }
    if (!(total > 0) || !std::isfinite(total)) return nullptr;
    return std::make_shared<const Distribution2D>(weights, width, height);
}

Color integrated_mean(const SkyImage& sky) {
    const int width = sky.image->width, height = sky.image->height;
    double r = 0, g = 0, b = 0;
    for (int y = 0; y < height; ++y) {
        const double band =
            std::cos(double(y) / height * kPi) - std::cos(double(y + 1) / height * kPi);
        for (int x = 0; x < width; ++x) {
            const Color c = pixel(sky, x, y);
            r += c.r * band;
            g += c.g * band;
            b += c.b * band;
        }
    }
    // Each pixel spans 2 pi / width of longitude: (2 pi / width) / 4 pi of the whole.
    const double share = 1.0 / (2.0 * width);
    return {float(r * share), float(g * share), float(b * share)};
}

}  // namespace

Vector3 sky_image_direction(Point2 uv) {
    float sin_theta = 0;
    return image_direction(uv, &sin_theta);
}

Sky::Sky(Color uniform) : mean_(uniform) {}

Sky::Sky(const SkyImage& image)
    : mean_(integrated_mean(image)),
      image_(image),
      cos_rotation_(std::cos(image.rotation)),
      sin_rotation_(std::sin(image.rotation)),
      distribution_(brightness_distribution(image)) {}

Vector3 Sky::to_image(Vector3 w) const {
    return {cos_rotation_ * w.x - sin_rotation_ * w.z, w.y,
            sin_rotation_ * w.x + cos_rotation_ * w.z};
}

Vector3 Sky::from_image(Vector3 w) const {
    return {cos_rotation_ * w.x + sin_rotation_ * w.z, w.y,
            -sin_rotation_ * w.x + cos_rotation_ * w.z};
}

Color Sky::radiance(Vector3 w) const {
    if (!image_) return mean_;
    const Point2 uv = image_uv(to_image(normalize(w)));
    const float s = uv.x * float(image_->image->width) - 0.5f;
    const float t = uv.y * float(image_->image->height) - 0.5f;
    if (!std::isfinite(s) || !std::isfinite(t)) return {};
    const float x0 = std::floor(s), y0 = std::floor(t);
    const float fx = s - x0, fy = t - y0;
    const int x = int(x0), y = int(y0);
    return pixel(*image_, x, y) * ((1 - fx) * (1 - fy)) +
           pixel(*image_, x + 1, y) * (fx * (1 - fy)) + pixel(*image_, x, y + 1) * ((1 - fx) * fy) +
           pixel(*image_, x + 1, y + 1) * (fx * fy);
}

Vector3 Sky::sample(Point2 u, float* pdf) const {
    if (!image_) {
        *pdf = is_black() ? 0 : uniform_sphere_pdf();
        return sample_uniform_sphere(u);
    }
    *pdf = 0;
    if (!distribution_) return {0, 1, 0};
    float pdf_uv = 0;
    const Point2 uv = distribution_->sample(u, &pdf_uv);
    float sin_theta = 0;
    const Vector3 w = image_direction(uv, &sin_theta);
    if (pdf_uv > 0 && sin_theta > 0) *pdf = pdf_uv / (2 * kPi * kPi * sin_theta);
    return from_image(w);
}

float Sky::pdf(Vector3 w) const {
    if (!image_) return is_black() ? 0 : uniform_sphere_pdf();
    if (!distribution_) return 0;
    const Vector3 local = to_image(normalize(w));
    const float sin_theta = std::sqrt(std::max(0.0f, 1 - local.y * local.y));
    if (!(sin_theta > 0)) return 0;
    return distribution_->pdf(image_uv(local)) / (2 * kPi * kPi * sin_theta);
}

}  // namespace glint
