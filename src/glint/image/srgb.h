// The sRGB transfer function (IEC 61966-2-1) between linear values and encoded values in [0, 1].
#pragma once

#include <algorithm>
#include <cmath>

namespace glint {

inline float linear_to_srgb(float v) {
    v = std::clamp(v, 0.0f, 1.0f);
    return v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1 / 2.4f) - 0.055f;
}

inline float srgb_to_linear(float e) {
    e = std::clamp(e, 0.0f, 1.0f);
    return e <= 0.04045f ? e / 12.92f : std::pow((e + 0.055f) / 1.055f, 2.4f);
}

}  // namespace glint
