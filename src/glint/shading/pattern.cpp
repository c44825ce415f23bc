// POV-Ray's solid patterns: the value of each kind, then frequency, phase and wave, with the
// point moved by turbulence first.
#include "glint/shading/pattern.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "glint/geometry/expression.h"
#include "glint/math/constants.h"
#include "glint/math/interval.h"
#include "glint/sampling/random.h"
#include "glint/shading/noise.h"

namespace glint {

namespace {

// A point in the unit cell (x, y, z) at random, the same each time: crackle's feature point.
Vector3 feature_point(std::int64_t x, std::int64_t y, std::int64_t z) {
    std::uint64_t h =
        mix64(std::uint64_t(x) * 0x9e3779b97f4a7c15ull ^ std::uint64_t(y) * 0xc2b2ae3d27d4eb4full ^
              std::uint64_t(z) * 0x165667b19e3779f9ull);
    const auto unit = [&h] {
        h = mix64(h);
        return float(h >> 40) * 0x1p-24f;
    };
    const float a = unit(), b = unit(), c = unit();
    return {a, b, c};
}

// Worley's cellular noise: the second-nearest feature point's distance minus the nearest's.
float crackle(Point3 p) {
    const double fx = std::floor(double(p.x)), fy = std::floor(double(p.y)),
                 fz = std::floor(double(p.z));
    if (!(std::abs(fx) < 0x1p52 && std::abs(fy) < 0x1p52 && std::abs(fz) < 0x1p52)) return 0;
    const auto cx = std::int64_t(fx), cy = std::int64_t(fy), cz = std::int64_t(fz);
    const Vector3 local{float(double(p.x) - fx), float(double(p.y) - fy), float(double(p.z) - fz)};
    float nearest = kInfinity, second = kInfinity;
    for (int i = -1; i <= 1; ++i)
        for (int j = -1; j <= 1; ++j)
            for (int k = -1; k <= 1; ++k) {
                const Vector3 at =
                    Vector3{float(i), float(j), float(k)} + feature_point(cx + i, cy + j, cz + k);
                const float d = length(at - local);
                if (d < nearest) {
                    second = nearest;
                    nearest = d;
                } else if (d < second) {
                    second = d;
                }
            }
    return std::clamp(second - nearest, 0.0f, 1.0f);
}

// POV-Ray's hexagons: side 1 in the x-z plane, a corner on the x axis, one centred at the
// origin. The centres are (1.5 i, sqrt(3) (j + i / 2)); the point's is the nearest, found in the
// two columns i it can lie in, and (j + 2 i) mod 3 colours the tiling in three.
float hexagon(Point3 p) {
    const double x = p.x, z = p.z, root3 = std::sqrt(3.0);
    const double column = std::floor(x / 1.5);
    if (!(std::abs(column) < 0x1p40 && std::abs(z) < 0x1p40)) return 0;
    double best = kInfinity;
    std::int64_t colour = 0;
    for (const double i : {column, column + 1}) {
        const double j = std::round(z / root3 - i / 2);
        const double dx = x - 1.5 * i, dz = z - root3 * (j + i / 2);
        if (const double d = dx * dx + dz * dz; d < best) {
            best = d;
            colour = (std::int64_t(j) + 2 * std::int64_t(i)) % 3;
        }
    }
    return float((colour + 3) % 3) / 2;
}

// POV-Ray's bricks: courses of height size.y, each brick size.x along x and size.z along z, the
// joints of every other course half a brick along; mortar of the given width at the bottom of a
// course and the start of a brick. POV-Ray first moves the point by the mortar and 0.001.
float brick(const PatternSpec& spec, Point3 p) {
    const auto fraction = [](double v) { return v - std::floor(v); };
    const double mortar = spec.mortar, shift = mortar + 1e-3;
    const double x = p.x + shift, y = p.y + shift, z = p.z + shift;
    const double w = spec.brick_size.x, h = spec.brick_size.y, d = spec.brick_size.z;
    if (fraction(y / h) <= mortar / h) return 0;
    const bool first_half = fraction(y / (2 * h)) <= 0.5;
    if (fraction(x / w + (first_half ? 0 : 0.5)) <= mortar / w) return 0;
    if (fraction(z / d + (first_half ? 0.5 : 0)) <= mortar / d) return 0;
    return 1;
}

// POV-Ray's rings round the wave sources: the mean of sin(2 pi (d f + phase)) / f over them, f
// the source's frequency (waves) or 1 (ripples).
float rings(const PatternSpec& spec, Point3 p, bool own_frequencies) {
    double sum = 0;
    const auto sources = wave_sources();
    for (const WaveSource& source : sources) {
        float d = length(p - to_point(source.at));
        if (d == 0) d = 1;
        const double f = own_frequencies ? source.frequency : 1;
        sum += std::sin(2 * kPi * (d * spec.frequency * f + spec.phase)) / f;
    }
    return float(sum / double(sources.size()));
}

// POV-Ray's Mandelbrot pattern: z <- z^2 + c from z = c = x + iy; outside, the iterations it
// took to leave the circle of radius 2 over the most; inside, 1.
float mandel(const PatternSpec& spec, Point3 p) {
    const double cx = p.x, cy = p.y;
    double a = cx, b = cy;
    for (int i = 0; i < spec.iterations; ++i) {
        const double a2 = a * a, b2 = b * b;
        b = 2 * a * b + cy;
        a = a2 - b2 + cx;
        if (a * a + b * b > 4) return float(i) / float(spec.iterations);
    }
    return 1;
}

// The angle round z from -y, over a turn, as POV-Ray's spirals measure it.
float turn_round_z(float x, float y, float rad) {
    if (rad == 0) return 0;
    const float half_pi = 0.5f * kPi;
    const float phi = x < 0 ? 3 * half_pi - std::asin(y / rad) : half_pi + std::asin(y / rad);
    return phi / (2 * kPi);
}

float triangle_wave(float v) {
    const float f = v - std::floor(v);
    return f <= 0.5f ? 2 * f : 2 * (1 - f);
}

float raw_value(const PatternSpec& spec, Point3 p) {
    const float x = p.x, y = p.y, z = p.z;
    switch (spec.kind) {
        case PatternKind::agate:
            return 0.5f + 0.5f * std::sin(2 * kPi * (z + turbulence(p, spec.octaves)));
        case PatternKind::bozo:
            return std::clamp(0.5f + 0.5f * perlin_noise(p), 0.0f, 1.0f);
        case PatternKind::boxed:
            return std::max(0.0f, 1 - std::max({std::abs(x), std::abs(y), std::abs(z)}));
        case PatternKind::brick:
            return brick(spec, p);
        case PatternKind::hexagon:
            return hexagon(p);
        case PatternKind::checker: {
            const double sum = checker_cell(x) + checker_cell(y) + checker_cell(z);
            return std::abs(std::fmod(sum, 2.0)) == 1.0 ? 1.0f : 0.0f;
        }
        case PatternKind::crackle:
            return crackle(p);
        case PatternKind::cylindrical:
            return std::max(0.0f, 1 - std::sqrt(x * x + z * z));
        case PatternKind::gradient:
            return dot(to_vector(p), spec.direction);
        case PatternKind::granite:
            return granite_pattern(p, spec.octaves);
        case PatternKind::leopard: {
            const float s = std::sin(x) + std::sin(y) + std::sin(z);
            return s * s / 9;
        }
        case PatternKind::marble:
            return x;
        case PatternKind::onion:
            return length(to_vector(p));
        case PatternKind::planar:
            return std::max(0.0f, 1 - std::abs(y));
        case PatternKind::radial:
            return -std::atan2(z, x) / (2 * kPi);
        case PatternKind::spherical:
            return std::max(0.0f, 1 - length(to_vector(p)));
        case PatternKind::wood:
            return std::sqrt(x * x + y * y);
        case PatternKind::mandel:
            return mandel(spec, p);
        case PatternKind::ripples:
            return 0.5f * (1 + rings(spec, p, false));
        case PatternKind::waves:
            return 0.2f * (2.5f + rings(spec, p, true));
        case PatternKind::spiral1:
        case PatternKind::spiral2: {
            const float rad = std::sqrt(x * x + y * y);
            const float s = z + rad + spec.arms * turn_round_z(x, y, rad);
            return spec.kind == PatternKind::spiral1 ? s : triangle_wave(rad) + triangle_wave(s);
        }
        case PatternKind::function:
            return float(spec.function->value(p));
        case PatternKind::wrinkles: {
            // Noise in [0, 1], as POV-Ray's.
            float sum = 0, weight = 1, scale = 1;
            for (int i = 0; i < 10; ++i, weight *= 0.5f, scale *= 2)
                sum +=
                    weight * std::clamp(0.5f + 0.5f * perlin_noise(to_point(to_vector(p) * scale)),
                                        0.0f, 1.0f);
            return sum / 2;
        }
    }
    return 0;
}

float shaped(const PatternSpec& spec, float f) {
    switch (spec.wave) {
        case PatternWave::ramp:
            return f;
        case PatternWave::triangle:
            return f <= 0.5f ? 2 * f : 2 * (1 - f);
        case PatternWave::sine:
            return 0.5f * (1 + std::sin(2 * kPi * f));
        case PatternWave::scallop:
            return std::abs(std::sin(kPi * f));
        case PatternWave::cubic:
            return f * f * (3 - 2 * f);
        case PatternWave::poly:
            return std::pow(f, spec.exponent);
    }
    return f;
}

}  // namespace

std::span<const WaveSource> wave_sources() {
    // The frequencies from POV-Ray's linear congruential generator seeded at -560851967.
    static const auto sources = [] {
        constexpr int kCount = 10;
        std::array<WaveSource, kCount> s{};
        std::uint32_t next = std::uint32_t(-560851967);
        const double golden = kPi * (3 - std::sqrt(5.0));
        for (int i = 0; i < kCount; ++i) {
            const double y = 1 - (i + 0.5) * 2 / kCount, r = std::sqrt(1 - y * y);
            s[i].at = {float(r * std::cos(golden * i)), float(y), float(r * std::sin(golden * i))};
            next = next * 1812433253u + 12345u;
            s[i].frequency = float(double((next >> 16) & 0x7fff) / 32767 + 0.01);
        }
        return s;
    }();
    return sources;
}

bool is_list_pattern(PatternKind kind) {
    return kind == PatternKind::checker || kind == PatternKind::brick ||
           kind == PatternKind::hexagon;
}

PatternWave default_wave(PatternKind kind) {
    return kind == PatternKind::marble || kind == PatternKind::wood ||
                   kind == PatternKind::spiral1 || kind == PatternKind::spiral2
               ? PatternWave::triangle
               : PatternWave::ramp;
}

Point3 turbulent(const PatternSpec& spec, Point3 p) {
    if (spec.turbulence == Vector3{}) return p;
    Vector3 sum;
    float weight = 1, scale = 1;
    for (int i = 0; i < std::clamp(spec.octaves, 1, kMaxOctaves); ++i) {
        sum += vector_noise(Point3{p.x * scale, p.y * scale, p.z * scale}) * weight;
        weight *= spec.omega;
        scale *= spec.lambda;
    }
    return p +
           Vector3{spec.turbulence.x * sum.x, spec.turbulence.y * sum.y, spec.turbulence.z * sum.z};
}

double checker_cell(double v) {
    constexpr double kBoundaryTolerance = 1e-6;
    return std::floor(v + kBoundaryTolerance);
}

float pattern_value(const PatternSpec& spec, Point3 p) {
    if (!is_finite(p)) return 0;
    p = turbulent(spec, p);
    if (spec.warped) [[unlikely]]
        p = spec.after_turbulence(p);
    const float raw = raw_value(spec, p);
    if (is_list_pattern(spec.kind)) return raw;
    // In double, so that a far point keeps its fraction. Values in [0, 1] stay as they are (1
    // too, as in POV-Ray); the others wrap round.
    double f = double(raw) * spec.frequency + spec.phase;
    if (!(f >= 0 && f <= 1)) f -= std::floor(f);
    if (!(f >= 0 && f <= 1)) return 0;  // NaN
    return std::clamp(shaped(spec, float(f)), 0.0f, 1.0f);
}

}  // namespace glint
