#include "glint/image/colour_map.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "glint/image/srgb.h"

namespace glint {

namespace {

// Viridis at t = 0, 1/8, ..., 1, 8-bit sRGB; between them the map is linear in sRGB.
constexpr std::array<std::array<int, 3>, 9> kViridis = {{
    {68, 1, 84},     // #440154
    {71, 45, 123},   // #472d7b
    {59, 82, 139},   // #3b528b
    {44, 114, 142},  // #2c728e
    {33, 145, 140},  // #21918c
    {40, 174, 128},  // #28ae80
    {94, 201, 98},   // #5ec962
    {173, 220, 48},  // #addc30
    {253, 231, 37},  // #fde725
}};

Color from_srgb(float r, float g, float b) {
    return {srgb_to_linear(r), srgb_to_linear(g), srgb_to_linear(b)};
}

}  // namespace

Color colour_map(float t) {
    t = std::isnan(t) ? 0 : std::clamp(t, 0.0f, 1.0f);
    const float x = t * float(kViridis.size() - 1);
    const auto i = std::min(std::size_t(x), kViridis.size() - 2);
    const float f = x - float(i);
    const auto mix = [&](std::size_t c) {
        return (float(kViridis[i][c]) + f * float(kViridis[i + 1][c] - kViridis[i][c])) / 255;
    };
    return from_srgb(mix(0), mix(1), mix(2));
}

Color id_colour(std::int32_t id) {
    if (id < 0) return {};
    // Hue by the golden angle; lightness in three steps so that neighbours differ in both.
    const float hue = std::fmod(float(id) * 0.381966f, 1.0f) * 6;
    const float value = 0.95f - 0.25f * float(id % 3);
    const float saturation = 0.75f;
    const auto channel = [&](float n) {
        const float k = std::fmod(n + hue, 6.0f);
        return value - value * saturation * std::clamp(std::min(k, 4 - k), 0.0f, 1.0f);
    };
    return from_srgb(channel(5), channel(3), channel(1));
}

}  // namespace glint
