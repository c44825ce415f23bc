// Reconstruction filters: how much a sample counts towards each pixel around it, by its distance
// from the pixel's centre. Separable, f(dx, dy) = f(dx) f(dy), and 1 at the centre.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace glint {

// box: 1 inside the radius (today's per-pixel average with radius 0.5); tent: falls linearly to
// 0 at the radius; gaussian: Cook's (1986) Gaussian weighting, exp(-x^2 / (2 sigma^2)) less its
// value at the radius so that it reaches 0 there; mitchell: Mitchell and Netravali's (1988)
// cubic with parameters B and C, stretched to the radius (negative lobes sharpen).
enum class FilterKind { box, tent, gaussian, mitchell };

// The filters' names, sorted, as scene files and the command line write them.
std::span<const std::string_view> filter_names();
std::optional<FilterKind> filter_from_name(std::string_view name);

struct FilterSpec {
    FilterKind kind = FilterKind::box;
    float radius = 0.5f;  // in pixels, [kMinFilterRadius, kMaxFilterRadius]
    float sigma = 0.5f;   // gaussian: standard deviation in pixels, in (0, radius]
    float b = 1 / 3.0f;   // mitchell: B and C (1/3 each is what Mitchell and Netravali advise)
    float c = 1 / 3.0f;

    bool operator==(const FilterSpec&) const = default;
};

// The radius a kind takes when a scene names only the kind.
float default_filter_radius(FilterKind kind);

// A box of radius 1/2: each sample counts for its own pixel alone, the average of its samples.
inline bool is_one_pixel_box(const FilterSpec& spec) {
    return spec.kind == FilterKind::box && spec.radius == 0.5f;
}

// Below half a pixel some pixels would get no sample at all; beyond 8 a sample touches hundreds.
inline constexpr float kMinFilterRadius = 0.5f;
inline constexpr float kMaxFilterRadius = 8;

class Filter {
public:
    // The spec must be valid (describe_problem is empty).
    explicit Filter(const FilterSpec& spec);

    const FilterSpec& spec() const { return spec_; }
    float radius() const { return spec_.radius; }
    // The weight at offset x (pixels) along one axis: 1 at 0, 0 at |x| >= radius, except that the
    // box takes -radius < x <= radius, so that a sample on a border counts for one pixel only.
    float evaluate(float x) const;

private:
    FilterSpec spec_;
    float gaussian_floor_ = 0;  // the Gaussian at the radius
    float scale_ = 1;           // makes the weight 1 at 0
};

// Empty when the spec is valid, else why not ("filter radius must be in [0.5, 8], got 0.2").
std::string describe_problem(const FilterSpec& spec);

}  // namespace glint
