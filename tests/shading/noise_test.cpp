#include "glint/shading/noise.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>

#include "glint/math/constants.h"
#include "glint/sampling/random.h"

namespace glint::noise_test {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

// The i-th of a fixed set of points uniform in [lo, hi)^3.
Point3 random_point(std::uint64_t i, float lo, float hi, std::uint64_t seed = 1) {
    auto coordinate = [&](std::uint64_t axis) {
        return lo + (hi - lo) * random_float(i, 0, axis, seed);
    };
    return {coordinate(0), coordinate(1), coordinate(2)};
}

Vector3 random_unit_vector(std::uint64_t i, std::uint64_t seed) {
    const Point3 p = random_point(i, -1, 1, seed);
    return normalize(to_vector(p) + Vector3{0, 0, 1e-3f});
}

void expect_near(Vector3 a, Vector3 b, float tol) {
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
    EXPECT_NEAR(a.z, b.z, tol);
}

void expect_near(Normal3 a, Normal3 b, float tol) { expect_near(to_vector(a), to_vector(b), tol); }

void expect_near(Color a, Color b, float tol) {
    EXPECT_NEAR(a.r, b.r, tol);
    EXPECT_NEAR(a.g, b.g, tol);
    EXPECT_NEAR(a.b, b.b, tol);
}

float quintic(float t) { return 6 * std::pow(t, 5.0f) - 15 * std::pow(t, 4.0f) + 10 * t * t * t; }

// ---- Perlin noise ----

TEST(PerlinNoise, IsZeroAtLatticePoints) {
    for (const Point3 p :
         {Point3{0, 0, 0}, Point3{1, 2, 3}, Point3{-1, -5, 7}, Point3{-256, 255, -1000},
          Point3{1e6f, -3e6f, 17}, Point3{1e7f, 0, -1e7f}}) {
        EXPECT_EQ(perlin_noise(p), 0) << p.x << " " << p.y << " " << p.z;
    }
}

TEST(PerlinNoise, LatticeGradientsAreCubeEdgeDirections) {
    // At a lattice point the fade's derivative vanishes: the gradient is the corner's own, one of
    // the 12 vectors with two components +-1 and one 0.
    for (int i = -5; i <= 5; ++i) {
        const Vector3 g = perlin_noise_gradient({float(i), float(2 * i), float(-3 * i + 1)});
        EXPECT_EQ(std::abs(g.x) + std::abs(g.y) + std::abs(g.z), 2);
        EXPECT_EQ(length_squared(g), 2);
    }
}

TEST(PerlinNoise, AlongALatticeEdgeBlendsTheTwoCornerRampsWithTheQuinticFade) {
    // On the edge from (0,0,0) to (1,0,0) only those two corners weigh in:
    // n(t) = (1 - s) g0.x t + s g1.x (t - 1), s = 6t^5 - 15t^4 + 10t^3, with g0, g1 the corners'
    // gradients, read back at the lattice points where the noise's gradient equals them.
    const float g0 = perlin_noise_gradient({0, 0, 0}).x, g1 = perlin_noise_gradient({1, 0, 0}).x;
    for (const float t : {0.125f, 0.25f, 0.5f, 0.7f, 0.9f}) {
        const float s = quintic(t);
        EXPECT_NEAR(perlin_noise({t, 0, 0}), (1 - s) * g0 * t + s * g1 * (t - 1), 1e-6) << t;
    }
    // The same on an edge below zero, from (-3,-2,-1) to (-2,-2,-1).
    const float h0 = perlin_noise_gradient({-3, -2, -1}).x;
    const float h1 = perlin_noise_gradient({-2, -2, -1}).x;
    for (const float t : {0.125f, 0.5f, 0.875f}) {
        const float s = quintic(t);
        EXPECT_NEAR(perlin_noise({-3 + t, -2, -1}), (1 - s) * h0 * t + s * h1 * (t - 1), 1e-6);
    }
}

TEST(PerlinNoise, StaysWithinItsRangeAndUsesMostOfIt) {
    float lo = 0, hi = 0;
    for (std::uint64_t i = 0; i < 200000; ++i) {
        const float n = perlin_noise(random_point(i, -100, 100));
        ASSERT_GE(n, -1.1f);
        ASSERT_LE(n, 1.1f);
        lo = std::min(lo, n);
        hi = std::max(hi, n);
    }
    EXPECT_LT(lo, -0.7f);
    EXPECT_GT(hi, 0.7f);
}

TEST(PerlinNoise, IsDeterministic) {
    for (std::uint64_t i = 0; i < 100; ++i) {
        const Point3 p = random_point(i, -50, 50);
        EXPECT_EQ(perlin_noise(p), perlin_noise(p));
        EXPECT_EQ(perlin_noise_gradient(p), perlin_noise_gradient(p));
    }
}

TEST(PerlinNoise, SmallStepsGiveSmallChangesAlsoAcrossCellFaces) {
    // |grad| stays below 3.5, so a step of 1e-4 changes the noise by less than 1e-3.
    for (std::uint64_t i = 0; i < 2000; ++i) {
        const Point3 p = random_point(i, -20, 20);
        const Vector3 step = random_unit_vector(i, 2) * 1e-4f;
        EXPECT_LT(std::abs(perlin_noise(p + step) - perlin_noise(p)), 1e-3f);
    }
    // Straddling the faces x = 2, y = -3 and z = 0.
    for (const Point3 p : {Point3{2, 0.3f, 0.6f}, Point3{0.4f, -3, 5.2f}, Point3{-7.7f, 1.1f, 0}}) {
        const Vector3 d{1e-4f, 1e-4f, 1e-4f};
        EXPECT_LT(std::abs(perlin_noise(p + d) - perlin_noise(p - d)), 1e-3f);
    }
}

TEST(PerlinNoise, IsNotConstantAndAveragesToZeroOverALargeRegion) {
    // One full period (256^3 cells), sampled at random: a gradient noise has mean 0.
    double sum = 0, sum_squares = 0;
    const int count = 400000;
    for (int i = 0; i < count; ++i) {
        const double n = perlin_noise(random_point(std::uint64_t(i), 0, 256, 3));
        sum += n;
        sum_squares += n * n;
    }
    const double mean = sum / count, deviation = std::sqrt(sum_squares / count - mean * mean);
    EXPECT_GT(deviation, 0.1);
    EXPECT_LT(std::abs(mean), 5 * deviation / std::sqrt(double(count)));  // five standard errors
}

TEST(PerlinNoise, RepeatsEvery256CellsForAnyCoordinate) {
    // Dyadic coordinates, so that adding multiples of 256 is exact in float.
    const Point3 p{0.375f, -1.625f, 2.5f};
    EXPECT_EQ(perlin_noise(p), perlin_noise(p + Vector3{256, -512, 768}));
    EXPECT_EQ(perlin_noise({-0.375f, 0.25f, 0.5f}), perlin_noise({-256.375f, 0.25f, 0.5f}));
    // Past 2^30 the cell index is reduced by fmod rather than a cast: 2^30 + 128 = 128 mod 256,
    // -(2^30 + 128) = -128 = 128 mod 256, and every float from 2^32 on is a multiple of 256.
    const float big = 0x1p30f + 128;
    EXPECT_EQ(perlin_noise({big, 0.25f, 0.5f}), perlin_noise({128, 0.25f, 0.5f}));
    EXPECT_EQ(perlin_noise({-big, 0.25f, 0.5f}), perlin_noise({128, 0.25f, 0.5f}));
    EXPECT_EQ(perlin_noise({0.75f, 3e38f, 0.5f}), perlin_noise({0.75f, 0, 0.5f}));
    EXPECT_EQ(perlin_noise({0.75f, 0.5f, -3e38f}), perlin_noise({0.75f, 0.5f, 0}));
    EXPECT_NE(perlin_noise({0.75f, 0.5f, 0.25f}), 0);
}

TEST(PerlinNoise, LargeCoordinatesGiveFiniteValues) {
    for (std::uint64_t i = 0; i < 1000; ++i) {
        const Point3 p = random_point(i, -1e7f, 1e7f);
        const float n = perlin_noise(p);
        EXPECT_TRUE(std::abs(n) <= 1.1f) << n;
        EXPECT_TRUE(is_finite(perlin_noise_gradient(p)));
    }
}

TEST(PerlinNoise, NonFiniteInputGivesZero) {
    for (const Point3 p : {Point3{kNaN, 0.5f, 0.5f}, Point3{0.5f, kInf, 0.5f},
                           Point3{0.5f, 0.5f, -kInf}, Point3{kNaN, kNaN, kNaN}}) {
        EXPECT_EQ(perlin_noise(p), 0);
        EXPECT_EQ(perlin_noise_gradient(p), Vector3{});
        EXPECT_EQ(fractal_sum(p, 4), 0);
        EXPECT_EQ(turbulence(p, 4), 0);
        EXPECT_EQ(fractal_sum_gradient(p, 4), Vector3{});
        EXPECT_EQ(turbulence_gradient(p, 4), Vector3{});
    }
}

// ---- Gradients ----

// |analytic - finite difference| within rel of the gradient's length (or of 1 near a zero).
void expect_gradients_agree(Vector3 analytic, Vector3 numeric, float rel) {
    const float tol = rel * std::max(1.0f, length(analytic));
    EXPECT_LT(length(analytic - numeric), tol)
        << "analytic " << analytic.x << " " << analytic.y << " " << analytic.z << ", numeric "
        << numeric.x << " " << numeric.y << " " << numeric.z;
}

TEST(PerlinNoiseGradient, MatchesCentralDifferences) {
    for (std::uint64_t i = 0; i < 2000; ++i) {
        const Point3 p = random_point(i, -8, 8, 4);
        const Vector3 numeric = gradient_of([](Point3 q) { return perlin_noise(q); }, p, 1e-3f);
        expect_gradients_agree(perlin_noise_gradient(p), numeric, 2e-3f);
    }
}

TEST(FractalSumGradient, MatchesCentralDifferences) {
    for (std::uint64_t i = 0; i < 500; ++i) {
        const Point3 p = random_point(i, -4, 4, 5);
        auto f = [](Point3 q) { return fractal_sum(q, 4, 2.0f, 0.6f); };
        expect_gradients_agree(fractal_sum_gradient(p, 4, 2.0f, 0.6f), gradient_of(f, p, 3e-4f),
                               5e-3f);
    }
}

TEST(TurbulenceGradient, MatchesCentralDifferencesAwayFromItsCreases) {
    int checked = 0;
    for (std::uint64_t i = 0; i < 500; ++i) {
        const Point3 p = random_point(i, -4, 4, 6);
        // Skip points where an octave's noise is near 0: |noise| has a crease there, and the
        // differences' steps (at most 4 * 3e-4 in that octave, where |grad| < 3.5) must not cross
        // it.
        bool near_crease = false;
        for (float f = 1; f <= 4; f *= 2) {
            near_crease |= std::abs(perlin_noise(to_point(to_vector(p) * f))) < 0.02f;
        }
        if (near_crease) continue;
        ++checked;
        auto f = [](Point3 q) { return turbulence(q, 3); };
        expect_gradients_agree(turbulence_gradient(p, 3), gradient_of(f, p, 3e-4f), 5e-3f);
    }
    EXPECT_GT(checked, 300);
}

TEST(GradientOf, IsExactForALinearField) {
    auto f = [](Point3 q) { return 2 * q.x - 3 * q.y + 0.5f * q.z; };
    expect_near(gradient_of(f, {0.25f, -1.5f, 4}, 0.125f), {2, -3, 0.5f}, 1e-6f);
}

// ---- fBm and turbulence ----

TEST(FractalSum, OneOctaveIsTheNoiseAndTurbulenceItsMagnitude) {
    for (std::uint64_t i = 0; i < 200; ++i) {
        const Point3 p = random_point(i, -30, 30, 7);
        EXPECT_EQ(fractal_sum(p, 1), perlin_noise(p));
        EXPECT_EQ(fractal_sum(p, 1, 3.0f, 0.1f), perlin_noise(p));
        EXPECT_EQ(turbulence(p, 1), std::abs(perlin_noise(p)));
        EXPECT_EQ(fractal_sum_gradient(p, 1), perlin_noise_gradient(p));
        const Vector3 g = perlin_noise_gradient(p);
        EXPECT_EQ(turbulence_gradient(p, 1), perlin_noise(p) < 0 ? -g : g);
    }
}

TEST(FractalSum, AddsOctavesWithTheirGainAndLacunarity) {
    // Two octaves, lacunarity 3, gain 0.25: noise(p) + 0.25 noise(3p).
    const Point3 p{0.3f, -1.7f, 2.2f};
    const float expected = perlin_noise(p) + 0.25f * perlin_noise({3 * p.x, 3 * p.y, 3 * p.z});
    EXPECT_FLOAT_EQ(fractal_sum(p, 2, 3, 0.25f), expected);
    // Turbulence, three octaves: |n(p)| + |n(2p)| / 2 + |n(4p)| / 4.
    const float turb = std::abs(perlin_noise(p)) +
                       std::abs(perlin_noise({2 * p.x, 2 * p.y, 2 * p.z})) / 2 +
                       std::abs(perlin_noise({4 * p.x, 4 * p.y, 4 * p.z})) / 4;
    EXPECT_FLOAT_EQ(turbulence(p, 3), turb);
}

TEST(FractalSum, NoOctavesGiveZero) {
    EXPECT_EQ(fractal_sum({0.3f, 0.4f, 0.5f}, 0), 0);
    EXPECT_EQ(fractal_sum({0.3f, 0.4f, 0.5f}, -3), 0);
    EXPECT_EQ(turbulence({0.3f, 0.4f, 0.5f}, 0), 0);
    EXPECT_EQ(turbulence_gradient({0.3f, 0.4f, 0.5f}, -1), Vector3{});
}

TEST(Turbulence, IsNonNegativeBoundedAndVaries) {
    float lo = 10, hi = 0;
    for (std::uint64_t i = 0; i < 20000; ++i) {
        const float t = turbulence(random_point(i, -50, 50, 8), 8);
        ASSERT_GE(t, 0);
        ASSERT_LT(t, 2.1f);
        lo = std::min(lo, t);
        hi = std::max(hi, t);
    }
    EXPECT_GT(hi - lo, 0.5f);
}

TEST(Turbulence, ManyOctavesAndHugeCoordinatesStayFinite) {
    // Octaves past kMaxOctaves are ignored; frequencies overflowing to infinity add 0.
    EXPECT_EQ(turbulence({0.3f, 0.2f, 0.1f}, 1 << 30), turbulence({0.3f, 0.2f, 0.1f}, kMaxOctaves));
    EXPECT_TRUE(std::isfinite(turbulence({3e38f, -3e38f, 1e30f}, 8)));
    EXPECT_TRUE(std::isfinite(fractal_sum({1e7f, 0.5f, -1e7f}, 8, 2, 0.5f)));
    EXPECT_FALSE(std::isnan(fractal_sum({0.5f, 0.5f, 0.5f}, 30, 1e10f, 1e10f)));
    EXPECT_FALSE(std::isnan(fractal_sum({0, 0, 0}, 30, 1e10f, 1e10f)));
    EXPECT_TRUE(is_finite(turbulence_gradient({3e38f, 0.5f, 1e7f}, 8)));
}

// ---- Patterns ----

TEST(Patterns, StayInTheUnitIntervalAndVary) {
    struct Range {
        float lo = 10, hi = -10;
        void add(float v) {
            ASSERT_GE(v, 0);
            ASSERT_LE(v, 1);
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
    } marble, wood, granite;
    for (std::uint64_t i = 0; i < 20000; ++i) {
        const Point3 p = random_point(i, -20, 20, 9);
        marble.add(marble_pattern(p, 1.5f, 6));
        wood.add(wood_pattern(p, 0.3f, 4));
        granite.add(granite_pattern(p, 6));
    }
    EXPECT_GT(marble.hi - marble.lo, 0.9f);
    EXPECT_GT(wood.hi - wood.lo, 0.9f);
    EXPECT_GT(granite.hi - granite.lo, 0.5f);
}

TEST(Patterns, MarbleWithoutTurbulenceIsASineAcrossX) {
    // 0.5 + 0.5 sin(2 pi x): 0.5 at x = 0, 1 at 1/4, 0.5 at 1/2, 0 at 3/4; y and z do not matter.
    EXPECT_NEAR(marble_pattern({0, 3, 4}, 0, 4), 0.5f, 1e-6);
    EXPECT_NEAR(marble_pattern({0.25f, -3, 9}, 0, 4), 1, 1e-6);
    EXPECT_NEAR(marble_pattern({10.5f, 1, 1}, 0, 4), 0.5f, 1e-6);
    EXPECT_NEAR(marble_pattern({-0.25f, 7, 2}, 0, 4), 0, 1e-6);
    // x = 1/12: sin(pi / 6) = 1/2, so 0.75.
    EXPECT_NEAR(marble_pattern({1.0f / 12, 0, 0}, 0, 4), 0.75f, 1e-6);
}

TEST(Patterns, MarbleTurbulenceShiftsThePhase) {
    const Point3 p{0.1f, 0.35f, 0.8f};
    const double phase = p.x + 0.7 * turbulence(p, 5);
    EXPECT_NEAR(marble_pattern(p, 0.7f, 5), 0.5 + 0.5 * std::sin(2 * double(kPi) * phase), 1e-5);
}

TEST(Patterns, WoodWithoutTurbulenceIsTheRadiusFraction) {
    EXPECT_NEAR(wood_pattern({1.5f, 9, 2}, 0, 4), 0.5f, 1e-6);     // radius 2.5
    EXPECT_NEAR(wood_pattern({3, -2, 4}, 0, 4), 0, 1e-6);          // radius 5
    EXPECT_NEAR(wood_pattern({-3.25f, 0, 0}, 0, 4), 0.25f, 1e-6);  // radius 3.25
    EXPECT_NEAR(wood_pattern({0, 0, -0.75f}, 0, 4), 0.75f, 1e-6);
}

TEST(Patterns, GraniteIsHalfTheTurbulenceAtFourTimesTheFrequency) {
    for (std::uint64_t i = 0; i < 100; ++i) {
        const Point3 p = random_point(i, -5, 5, 10);
        const float t = turbulence({4 * p.x, 4 * p.y, 4 * p.z}, 5) / 2;
        EXPECT_FLOAT_EQ(granite_pattern(p, 5), std::min(t, 1.0f));
    }
}

TEST(Patterns, HugeAndNonFiniteInputStayInTheUnitInterval) {
    auto in_unit = [](float v) { return v >= 0 && v <= 1; };
    for (const Point3 p : {Point3{3e38f, 1, 1}, Point3{-1e7f, 1e7f, 3}, Point3{1, -3e38f, 3e38f}}) {
        EXPECT_TRUE(in_unit(marble_pattern(p, 2, 6)));
        EXPECT_TRUE(in_unit(wood_pattern(p, 2, 6)));
        EXPECT_TRUE(in_unit(granite_pattern(p, 6)));
        EXPECT_TRUE(in_unit(marble_pattern(p, kInf, 6)));
        EXPECT_TRUE(in_unit(wood_pattern(p, kNaN, 6)));
    }
    for (const Point3 p : {Point3{kNaN, 1, 1}, Point3{1, kInf, 1}, Point3{1, 1, -kInf}}) {
        EXPECT_EQ(marble_pattern(p, 1, 4), 0);
        EXPECT_EQ(wood_pattern(p, 1, 4), 0);
        EXPECT_EQ(granite_pattern(p, 4), 0);
    }
}

// ---- Colour ramp ----

TEST(Ramp, TwoStopsBlendLinearly) {
    const std::array<Color, 2> stops{Color{1, 0, 0}, Color{0, 0, 1}};
    // t = 1/4: three quarters of the first, one quarter of the second.
    expect_near(ramp(stops, 0.25f), {0.75f, 0, 0.25f}, 1e-6f);
    expect_near(ramp(stops, 0.5f), {0.5f, 0, 0.5f}, 1e-6f);
    EXPECT_EQ(ramp(stops, 0), stops[0]);
    EXPECT_EQ(ramp(stops, 1), stops[1]);
}

TEST(Ramp, ThreeStopsAreEvenlySpaced) {
    const std::array<Color, 3> stops{Color{0, 0, 0}, Color{1, 1, 1}, Color{0, 2, 4}};
    EXPECT_EQ(ramp(stops, 0.5f), stops[1]);
    // t = 3/4 is halfway from the second stop (t = 1/2) to the third (t = 1).
    expect_near(ramp(stops, 0.75f), {0.5f, 1.5f, 2.5f}, 1e-6f);
    // t = 1/8 is a quarter of the way from the first to the second.
    expect_near(ramp(stops, 0.125f), {0.25f, 0.25f, 0.25f}, 1e-6f);
}

TEST(Ramp, ClampsTAndTakesTheFirstStopForNaN) {
    const std::array<Color, 3> stops{Color{0.1f, 0.2f, 0.3f}, Color{1, 1, 1}, Color{0, 2, 4}};
    EXPECT_EQ(ramp(stops, -0.5f), stops[0]);
    EXPECT_EQ(ramp(stops, -kInf), stops[0]);
    EXPECT_EQ(ramp(stops, 7), stops[2]);
    EXPECT_EQ(ramp(stops, kInf), stops[2]);
    EXPECT_EQ(ramp(stops, kNaN), stops[0]);
    EXPECT_EQ(ramp(std::span<const Color>(stops.data(), 1), 0.7f), stops[0]);
    EXPECT_EQ(ramp({}, 0.5f), Color{});
}

// ---- Bump mapping ----

const Normal3 kUp{0, 0, 1};

TEST(BumpNormal, NoGradientOrNoStrengthLeavesTheNormal) {
    const Normal3 n = normalize(Normal3{0.3f, -0.4f, 0.8f});
    EXPECT_EQ(bump_normal(n, {}, 2), n);
    EXPECT_EQ(bump_normal(n, {1, 2, 3}, 0), n);
    // The gradient's component along n is no slope of the surface.
    EXPECT_EQ(bump_normal(kUp, {0, 0, 5}, 1), kUp);
    expect_near(bump_normal(kUp, {1, 0, 5}, 1), bump_normal(kUp, {1, 0, 0}, 1), 1e-6f);
}

TEST(BumpNormal, TiltsAwayFromTheGradientByItsSlope) {
    // n = (0,0,1), g = (1,0,0), strength 1: normalize(-1, 0, 1), tilted 45 degrees.
    const float r = 1 / std::sqrt(2.0f);
    expect_near(bump_normal(kUp, {1, 0, 0}, 1), {-r, 0, r}, 1e-6f);
    expect_near(bump_normal(kUp, {0.5f, 0, 0}, 2), {-r, 0, r}, 1e-6f);
    // Slope 0.5 along y: (0, -0.5, 1) / sqrt(1.25), tilted atan(0.5) = 26.57 degrees.
    const Normal3 b = bump_normal(kUp, {0, 1, 0}, 0.5f);
    expect_near(b, {0, -0.5f / std::sqrt(1.25f), 1 / std::sqrt(1.25f)}, 1e-6f);
    EXPECT_NEAR(std::acos(dot(b, kUp)), std::atan(0.5f), 1e-5);
    // A negative strength carves instead of raising.
    expect_near(bump_normal(kUp, {1, 0, 0}, -1), {r, 0, r}, 1e-6f);
}

TEST(BumpNormal, ResultsAreUnitAndNeverFlip) {
    for (std::uint64_t i = 0; i < 5000; ++i) {
        const Normal3 n{random_unit_vector(i, 11)};
        const Vector3 g = to_vector(random_point(i, -10, 10, 12));
        const float strength = 5 * random_float(i, 0, 0, 13);
        const Normal3 b = bump_normal(n, g, strength);
        EXPECT_NEAR(length(to_vector(b)), 1, 1e-5);
        EXPECT_GT(dot(b, n), 0);
        // It leans away from the gradient's tangential part.
        const Vector3 tangential = g - dot(g, n) * to_vector(n);
        EXPECT_LE(dot(b, tangential), 1e-4f * length(tangential));
    }
}

TEST(BumpNormal, HugeGradientsAreLimitedToTheMaximumTilt) {
    for (const float big : {1e3f, 1e30f, 3e38f}) {
        const Normal3 b = bump_normal(kUp, {big, 0, 0}, big);
        EXPECT_NEAR(length(to_vector(b)), 1, 1e-6);
        EXPECT_NEAR(dot(b, kUp), std::cos(radians(kMaxBumpTiltDegrees)), 1e-5);
        EXPECT_LT(b.x, 0);
    }
}

TEST(BumpNormal, NonFiniteInputLeavesTheNormal) {
    EXPECT_EQ(bump_normal(kUp, {kNaN, 0, 0}, 1), kUp);
    EXPECT_EQ(bump_normal(kUp, {kInf, 0, 0}, 1), kUp);
    EXPECT_EQ(bump_normal(kUp, {1, -kInf, 0}, 1), kUp);
    EXPECT_EQ(bump_normal(kUp, {1, 0, 0}, kNaN), kUp);
    EXPECT_EQ(bump_normal(kUp, {1, 0, 0}, kInf), kUp);
}

TEST(BumpNormal, NoiseBumpsGiveUnitNormalsOnTheSameSide) {
    // The use it is made for: a sphere's normals bumped by turbulence.
    for (std::uint64_t i = 0; i < 1000; ++i) {
        const Vector3 n = random_unit_vector(i, 14);
        const Point3 p = to_point(n * 3);
        const Normal3 b = bump_normal(Normal3(n), turbulence_gradient(p, 6), 0.5f);
        EXPECT_NEAR(length(to_vector(b)), 1, 1e-5);
        EXPECT_GT(dot(to_vector(b), n), 0);
    }
}

}  // namespace
}  // namespace glint::noise_test
