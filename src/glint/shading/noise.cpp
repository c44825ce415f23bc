// Sums of Perlin's noise (sampling/perlin_noise.h): fBm and turbulence, the marble, wood and
// granite patterns, colour ramps and Blinn's bump mapping.
#include "glint/shading/noise.h"

#include <algorithm>
#include <cmath>

#include "glint/math/constants.h"

namespace glint {

namespace {

Point3 scaled(Point3 p, float s) { return to_point(to_vector(p) * s); }

float clamp01(float v) { return v > 0 ? (v < 1 ? v : 1) : 0; }  // NaN -> 0

}  // namespace

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
