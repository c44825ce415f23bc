// Linear RGB colour with float channels: the renderer's radiance and reflectance values.
#pragma once

#include <algorithm>
#include <cmath>

namespace glint {

struct Color {
    float r = 0, g = 0, b = 0;

    constexpr Color() = default;
    constexpr Color(float r_, float g_, float b_) : r(r_), g(g_), b(b_) {}
    static constexpr Color gray(float v) { return {v, v, v}; }

    constexpr Color operator+(Color c) const { return {r + c.r, g + c.g, b + c.b}; }
    constexpr Color operator-(Color c) const { return {r - c.r, g - c.g, b - c.b}; }
    constexpr Color operator*(Color c) const { return {r * c.r, g * c.g, b * c.b}; }
    constexpr Color operator*(float s) const { return {r * s, g * s, b * s}; }
    constexpr Color operator/(float s) const { return *this * (1 / s); }
    constexpr Color& operator+=(Color c) { return *this = *this + c; }
    constexpr Color& operator*=(Color c) { return *this = *this * c; }
    constexpr Color& operator*=(float s) { return *this = *this * s; }
    constexpr bool operator==(const Color&) const = default;
};

constexpr Color operator*(float s, Color c) { return c * s; }

constexpr float max_channel(Color c) { return std::max({c.r, c.g, c.b}); }
constexpr float mean(Color c) { return (c.r + c.g + c.b) / 3; }
constexpr bool is_black(Color c) { return c.r == 0 && c.g == 0 && c.b == 0; }
inline bool is_finite(Color c) {
    return std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b);
}

}  // namespace glint
