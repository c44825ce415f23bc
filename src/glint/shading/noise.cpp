// Perlin's improved gradient noise with its exact gradient, fBm and turbulence, the marble, wood
// and granite patterns, colour ramps and Blinn's bump mapping.
#include "glint/shading/noise.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <utility>

#include "glint/math/constants.h"
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

Point3 scaled(Point3 p, float s) { return to_point(to_vector(p) * s); }

float clamp01(float v) { return v > 0 ? (v < 1 ? v : 1) : 0; }  // NaN -> 0

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

Vector3 vector_noise(Point3 p) {
    return {perlin_noise(p), perlin_noise(p + Vector3{31.416f, -17.3f, 8.9f}),
            perlin_noise(p + Vector3{-23.7f, 41.1f, -5.3f})};
}

float fractal_sum(Point3 p, int octaves, float lacunarity, float gain) {
    float sum = 0, frequency = 1, amplitude = 1;
    for (int i = 0; i < std::min(octaves, kMaxOctaves); ++i) {
        sum += amplitude * perlin_noise(scaled(p, frequency));
        frequency *= lacunarity;
        amplitude *= gain;
        if (!std::isfinite(frequency) || !std::isfinite(amplitude)) break;  // absurd parameters
    }
    return sum;
}

Vector3 fractal_sum_gradient(Point3 p, int octaves, float lacunarity, float gain) {
    // d/dp noise(f p) = f * gradient(f p).
    Vector3 sum;
    float frequency = 1, amplitude = 1;
    for (int i = 0; i < std::min(octaves, kMaxOctaves); ++i) {
        sum += (amplitude * frequency) * perlin_noise_gradient(scaled(p, frequency));
        frequency *= lacunarity;
        amplitude *= gain;
        if (!std::isfinite(frequency) || !std::isfinite(amplitude)) break;  // absurd parameters
    }
    return sum;
}

float turbulence(Point3 p, int octaves) {
    float sum = 0, frequency = 1;
    for (int i = 0; i < std::min(octaves, kMaxOctaves); ++i) {
        sum += std::abs(perlin_noise(scaled(p, frequency))) / frequency;
        frequency *= 2;
    }
    return sum;
}

Vector3 turbulence_gradient(Point3 p, int octaves) {
    // d/dp |noise(f p)| / f = sign(noise(f p)) * gradient(f p): the frequencies cancel.
    Vector3 sum;
    float frequency = 1;
    for (int i = 0; i < std::min(octaves, kMaxOctaves); ++i) {
        const Point3 q = scaled(p, frequency);
        const float n = perlin_noise(q);
        if (n != 0) sum += std::copysign(1.0f, n) * perlin_noise_gradient(q);
        frequency *= 2;
    }
    return sum;
}

float marble_pattern(Point3 p, float turbulence_amount, int octaves) {
    if (!is_finite(p)) return 0;
    // Reduce the phase to one period in double first: sin of a huge float argument loses all
    // precision, and 2 pi x may overflow.
    const double phase = double(p.x) + double(turbulence_amount) * turbulence(p, octaves);
    const double period = phase - std::floor(phase);
    return clamp01(float(0.5 + 0.5 * std::sin(2 * double(kPi) * period)));
}

float wood_pattern(Point3 p, float turbulence_amount, int octaves) {
    if (!is_finite(p)) return 0;
    // hypot in double: x^2 + z^2 would overflow a float for |x| past 1.8e19.
    const double r =
        std::hypot(double(p.x), double(p.z)) + double(turbulence_amount) * turbulence(p, octaves);
    // Rounding the fraction to float can give exactly 1, which [0, 1] allows.
    return clamp01(float(r - std::floor(r)));
}

float granite_pattern(Point3 p, int octaves) {
    if (!is_finite(p)) return 0;
    return clamp01(0.5f * turbulence(scaled(p, 4), octaves));
}

Color ramp(std::span<const Color> stops, float t) {
    if (stops.empty()) return {};
    if (stops.size() == 1 || !(t > 0)) return stops.front();  // also NaN
    if (t >= 1) return stops.back();
    const float x = t * float(stops.size() - 1);
    const std::size_t i = std::min(std::size_t(x), stops.size() - 2);
    const float f = x - float(i);
    return stops[i] * (1 - f) + stops[i + 1] * f;
}

Normal3 bump_normal(Normal3 n, Vector3 height_gradient, float strength) {
    // In double: a huge gradient or strength must not overflow on its way to being limited.
    const double nx = n.x, ny = n.y, nz = n.z;
    const double gx = height_gradient.x, gy = height_gradient.y, gz = height_gradient.z;
    const double gn = gx * nx + gy * ny + gz * nz;
    // The gradient's part in the tangent plane, times strength: how far the normal leans.
    double tx = strength * (gx - gn * nx), ty = strength * (gy - gn * ny),
           tz = strength * (gz - gn * nz);
    const double lean = std::sqrt(tx * tx + ty * ty + tz * tz);
    if (!std::isfinite(lean) || lean == 0) return n;
    // n - t has the component 1 along n whatever t's length, so exact arithmetic never flips
    // it; limiting the lean to tan(max tilt) keeps it clear of the tangent plane in floats too.
    static const double max_lean = std::tan(double(radians(kMaxBumpTiltDegrees)));
    if (lean > max_lean) {
        const double s = max_lean / lean;
        tx *= s;
        ty *= s;
        tz *= s;
    }
    const double bx = nx - tx, by = ny - ty, bz = nz - tz;
    const double length = std::sqrt(bx * bx + by * by + bz * bz);
    return {float(bx / length), float(by / length), float(bz / length)};
}

}  // namespace glint
