// The noise patterns of noise.h sampled at scene points scaled to features, and what materials
// make of them.
#include "glint/shading/noise_texture.h"

#include <algorithm>

#include "glint/shading/noise.h"

namespace glint {

namespace {

float pattern_at(const NoiseSpec& s, Point3 q) {
    switch (s.pattern) {
        case NoisePattern::marble:
            return marble_pattern(q, s.turbulence, s.octaves);
        case NoisePattern::wood:
            return wood_pattern(q, s.turbulence, s.octaves);
        case NoisePattern::granite:
            return granite_pattern(q, s.octaves);
        case NoisePattern::turbulence:
            return std::min(1.0f, turbulence(q, s.octaves));
        case NoisePattern::fbm:
            return std::clamp(0.5f + 0.5f * fractal_sum(q, s.octaves), 0.0f, 1.0f);
    }
    return 0;
}

Point3 feature_space(const NoiseSpec& s, Point3 p) {
    return Point3{0, 0, 0} + to_vector(p) / s.scale;
}

}  // namespace

float noise_value(const NoiseSpec& spec, Point3 p) {
    return pattern_at(spec, feature_space(spec, p));
}

Vector3 noise_gradient(const NoiseSpec& spec, Point3 p) {
    const Point3 q = feature_space(spec, p);
    Vector3 g;
    switch (spec.pattern) {
        case NoisePattern::turbulence:
            g = turbulence_gradient(q, spec.octaves);
            break;
        case NoisePattern::fbm:
            g = 0.5f * fractal_sum_gradient(q, spec.octaves);
            break;
        default:
            // A thousandth of a feature: fine against granite's finest octaves.
            g = gradient_of([&](Point3 x) { return pattern_at(spec, x); }, q, 1e-3f);
    }
    return g / spec.scale;  // d/dp = (1 / scale) d/dq
}

Color evaluate(const NoiseTexture& texture, Point3 p) {
    return ramp(texture.colors, noise_value(texture.spec, p));
}

Normal3 bumped(const BumpMap& bump, Normal3 n, Point3 p) {
    return bump_normal(n, noise_gradient(bump.spec, p), bump.strength);
}

}  // namespace glint
