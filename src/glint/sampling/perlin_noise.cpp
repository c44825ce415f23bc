// Perlin's improved gradient noise and its exact gradient.
#include "glint/sampling/perlin_noise.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <utility>

#include "glint/sampling/random.h"

namespace glint {

namespace {

// A permutation of 0..255 by a Fisher-Yates shuffle driven by a SplitMix64 stream (mix64 of a
// Weyl sequence), stored twice over so that perm[perm[i] + j] needs no wrap. Computed at compile
// time; the seed is arbitrary but fixed, so the noise is the same in every build and run.
constexpr std::array<std::uint8_t, 512> make_permutation() {
    std::array<std::uint8_t, 256> perm{};
    for (int i = 0; i < 256; ++i) perm[i] = std::uint8_t(i);
    std::uint64_t state = 0x676c696e74ull;  // "glint"
    for (int i = 255; i > 0; --i) {
        state += 0x9e3779b97f4a7c15ull;
        // The modulo's bias is below 2^-56: negligible.
        const auto j = std::size_t(mix64(state) % std::uint64_t(i + 1));
        std::swap(perm[std::size_t(i)], perm[j]);
    }
    std::array<std::uint8_t, 512> twice{};
    for (std::size_t i = 0; i < 512; ++i) twice[i] = perm[i & 255];
    return twice;
}

constexpr std::array<std::uint8_t, 512> kPerm = make_permutation();

// The 12 directions from a cube's centre to its edges' midpoints (Perlin 2002), padded to 16 by
// repeating four of them so that a hash picks one with & 15 rather than a division by 12.
constexpr std::array<Vector3, 16> kGradients = {{
    {1, 1, 0},
    {-1, 1, 0},
    {1, -1, 0},
    {-1, -1, 0},
    {1, 0, 1},
    {-1, 0, 1},
    {1, 0, -1},
    {-1, 0, -1},
    {0, 1, 1},
    {0, -1, 1},
    {0, 1, -1},
    {0, -1, -1},
    {1, 1, 0},
    {-1, 1, 0},
    {0, -1, 1},
    {0, -1, -1},
}};

// The lattice cell holding p: its corner's index wrapped to 0..255 and p's offset in it, [0, 1].
struct Cell {
    int x, y, z;
    float fx, fy, fz;
};

// Floor's value reduced mod 256. A cast to int is defined only for |f| < 2^31; beyond 2^24
// every float is an integer, and fmod by 256 is exact, so huge coordinates wrap correctly too.
int wrap(float f) {
    const float reduced = std::abs(f) < 0x1p30f ? f : std::fmod(f, 256.0f);
    return int(reduced) & 255;  // two's complement: -1 & 255 = 255
}

Cell locate(Point3 p) {
    const float x0 = std::floor(p.x), y0 = std::floor(p.y), z0 = std::floor(p.z);
    return {wrap(x0), wrap(y0), wrap(z0), p.x - x0, p.y - y0, p.z - z0};
}

Vector3 gradient_at(const Cell& c, int dx, int dy, int dz) {
    const int h =
        kPerm[std::size_t(kPerm[std::size_t(kPerm[std::size_t(c.x + dx)] + c.y + dy)] + c.z + dz)];
    return kGradients[std::size_t(h & 15)];
}

// Perlin's 2002 fade curve and its derivative 30 t^2 (t - 1)^2: zero first and second
// derivatives at 0 and 1 keep the noise's second derivative continuous across cells.
float fade(float t) { return t * t * t * (t * (t * 6 - 15) + 10); }
float fade_derivative(float t) { return 30 * t * t * (t - 1) * (t - 1); }

float lerp(float t, float a, float b) { return a + t * (b - a); }

// A value with its gradient, so that the trilinear blend carries its derivative along.
struct Dual {
    float v;
    Vector3 g;
};

// lerp(t, a, b) where t itself varies with gradient dt.
Dual lerp(float t, Vector3 dt, Dual a, Dual b) {
    return {a.v + t * (b.v - a.v), a.g + t * (b.g - a.g) + (b.v - a.v) * dt};
}

}  // namespace

float perlin_noise(Point3 p) {
    if (!is_finite(p)) return 0;
    const Cell c = locate(p);
    auto corner = [&](int dx, int dy, int dz) {
        return dot(gradient_at(c, dx, dy, dz), Vector3{c.fx - dx, c.fy - dy, c.fz - dz});
    };
    const float u = fade(c.fx), v = fade(c.fy), w = fade(c.fz);
    const float y0 = lerp(v, lerp(u, corner(0, 0, 0), corner(1, 0, 0)),
                          lerp(u, corner(0, 1, 0), corner(1, 1, 0)));
    const float y1 = lerp(v, lerp(u, corner(0, 0, 1), corner(1, 0, 1)),
                          lerp(u, corner(0, 1, 1), corner(1, 1, 1)));
    return lerp(w, y0, y1);
}

Vector3 perlin_noise_gradient(Point3 p) {
    if (!is_finite(p)) return {};
    const Cell c = locate(p);
    // Each corner contributes g . (p - corner), whose gradient is g itself.
    auto corner = [&](int dx, int dy, int dz) {
        const Vector3 g = gradient_at(c, dx, dy, dz);
        return Dual{dot(g, Vector3{c.fx - dx, c.fy - dy, c.fz - dz}), g};
    };
    const float u = fade(c.fx), v = fade(c.fy), w = fade(c.fz);
    const Vector3 du{fade_derivative(c.fx), 0, 0};
    const Vector3 dv{0, fade_derivative(c.fy), 0};
    const Vector3 dw{0, 0, fade_derivative(c.fz)};
    const Dual y0 = lerp(v, dv, lerp(u, du, corner(0, 0, 0), corner(1, 0, 0)),
                         lerp(u, du, corner(0, 1, 0), corner(1, 1, 0)));
    const Dual y1 = lerp(v, dv, lerp(u, du, corner(0, 0, 1), corner(1, 0, 1)),
                         lerp(u, du, corner(0, 1, 1), corner(1, 1, 1)));
    return lerp(w, dw, y0, y1).g;
}

}  // namespace glint
