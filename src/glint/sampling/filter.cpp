// The four reconstruction filters' one-dimensional profiles.
#include "glint/sampling/filter.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace glint {

namespace {

float gaussian(float x, float sigma) { return std::exp(-x * x / (2 * sigma * sigma)); }

// Mitchell and Netravali's cubic on [-2, 2].
float mitchell(float x, float b, float c) {
    x = std::abs(x);
    if (x >= 2) return 0;
    if (x >= 1)
        return ((-b - 6 * c) * x * x * x + (6 * b + 30 * c) * x * x + (-12 * b - 48 * c) * x +
                (8 * b + 24 * c)) /
               6;
    return ((12 - 9 * b - 6 * c) * x * x * x + (-18 + 12 * b + 6 * c) * x * x + (6 - 2 * b)) / 6;
}

std::string format(float v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", double(v));
    return text;
}

constexpr std::string_view kFilterNames[] = {"box", "gaussian", "mitchell", "tent"};
constexpr FilterKind kFilterKinds[] = {FilterKind::box, FilterKind::gaussian, FilterKind::mitchell,
                                       FilterKind::tent};

}  // namespace

std::span<const std::string_view> filter_names() { return kFilterNames; }

std::optional<FilterKind> filter_from_name(std::string_view name) {
    for (std::size_t i = 0; i < std::size(kFilterNames); ++i)
        if (kFilterNames[i] == name) return kFilterKinds[i];
    return std::nullopt;
}

float default_filter_radius(FilterKind kind) {
    switch (kind) {
        case FilterKind::box:
            return 0.5f;
        case FilterKind::tent:
            return 1;
        case FilterKind::gaussian:
            return 1.5f;
        case FilterKind::mitchell:
            return 2;
    }
    return 0.5f;
}

Filter::Filter(const FilterSpec& spec) : spec_(spec) {
    if (spec.kind == FilterKind::gaussian) {
        gaussian_floor_ = gaussian(spec.radius, spec.sigma);
        scale_ = 1 / (1 - gaussian_floor_);
    } else if (spec.kind == FilterKind::mitchell) {
        scale_ = 1 / mitchell(0, spec.b, spec.c);
    }
}

float Filter::evaluate(float x) const {
    const float r = spec_.radius;
    switch (spec_.kind) {
        case FilterKind::box:
            return -r < x && x <= r ? 1.0f : 0.0f;
        case FilterKind::tent:
            return std::max(0.0f, 1 - std::abs(x) / r);
        case FilterKind::gaussian:
            return std::abs(x) >= r ? 0 : (gaussian(x, spec_.sigma) - gaussian_floor_) * scale_;
        case FilterKind::mitchell:
            return mitchell(2 * x / r, spec_.b, spec_.c) * scale_;
    }
    return 0;
}

std::string describe_problem(const FilterSpec& spec) {
    if (!(spec.radius >= kMinFilterRadius && spec.radius <= kMaxFilterRadius))
        return "filter radius must be in [" + format(kMinFilterRadius) + ", " +
               format(kMaxFilterRadius) + "], got " + format(spec.radius);
    // Beyond the radius the Gaussian is cut off; a sigma larger than that leaves nearly a box.
    if (spec.kind == FilterKind::gaussian && !(spec.sigma > 0 && spec.sigma <= spec.radius))
        return "gaussian filter sigma must be in (0, radius] = (0, " + format(spec.radius) +
               "], got " + format(spec.sigma);
    if (spec.kind == FilterKind::mitchell && !(6 - 2 * spec.b > 0))
        return "mitchell filter b must be < 3, got " + format(spec.b);
    return {};
}

}  // namespace glint
