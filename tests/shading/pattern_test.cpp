// POV-Ray's patterns against the values POV-Ray 3.7.0.10 itself gives: eval_pigment of
// pigment { <kind> color_map { [0 rgb 0] [1 rgb 1] } } at the points below, as its #debug
// printed them to four places.
#include "glint/shading/pattern.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace glint {
namespace {

PatternSpec spec_of(PatternKind kind) {
    PatternSpec spec;
    spec.kind = kind;
    spec.wave = default_wave(kind);
    return spec;
}

// The eight points POV-Ray was asked about: round the unit circle at height 0.3.
Point3 probe(int i) {
    const double a = i * std::acos(-1.0) / 4 + 0.1;
    return {float(std::cos(a)), 0.3f, float(std::sin(a))};
}

void expect_povray(const PatternSpec& spec, const std::vector<float>& povray, float scale = 1) {
    for (int i = 0; i < 8; ++i) {
        const Point3 p = probe(i);
        EXPECT_NEAR(pattern_value(spec, {p.x / scale, p.y / scale, p.z / scale}), povray[i], 6e-4)
            << "point " << i;
    }
}

TEST(Pattern, GeometricKindsGivePovRaysValues) {
    expect_povray(spec_of(PatternKind::radial),
                  {0.9841f, 0.8591f, 0.7341f, 0.6091f, 0.4841f, 0.3591f, 0.2341f, 0.1091f});
    // wood scale 0.3: rings round z through the triangle wave.
    expect_povray(spec_of(PatternKind::wood),
                  {0.9283f, 0.6698f, 0.1078f, 0.4650f, 0.9283f, 0.6698f, 0.1078f, 0.4650f}, 0.3f);
    // checker rgb 1 rgb 0 printed 1 1 0 0 ...: the first colour (index 0) in even cells.
    expect_povray(spec_of(PatternKind::checker), {0, 0, 1, 1, 0, 0, 1, 1});
    expect_povray(spec_of(PatternKind::planar), std::vector<float>(8, 0.7f));
    // A plane's points at y = 0 rounded to -1e-8 stay in the cells above it (checker_cell).
    EXPECT_EQ(pattern_value(spec_of(PatternKind::checker), {0.5f, -1e-8f, 0.5f}), 0);
    EXPECT_EQ(checker_cell(-1e-8), 0);
    EXPECT_EQ(checker_cell(-2e-6), -1);
    EXPECT_EQ(checker_cell(2.9999999), 3);
    expect_povray(spec_of(PatternKind::spherical), std::vector<float>(8, 0));
    expect_povray(spec_of(PatternKind::cylindrical), std::vector<float>(8, 0));
    expect_povray(spec_of(PatternKind::boxed),
                  {0.0050f, 0.2258f, 0.0050f, 0.2258f, 0.0050f, 0.2258f, 0.0050f, 0.2258f});
    PatternSpec twice = spec_of(PatternKind::radial);
    twice.frequency = 2;
    expect_povray(twice, {0.9682f, 0.7182f, 0.4682f, 0.2182f, 0.9682f, 0.7182f, 0.4681f, 0.2181f});
}

// Mandelbrot and spiral patterns: mandel 20, spiral1 3 and spiral2 5 (through their default
// triangle wave) as POV-Ray's eval_pigment gives them.
TEST(Pattern, MandelAndSpiralsGivePovRaysValues) {
    PatternSpec mandel = spec_of(PatternKind::mandel);
    mandel.iterations = 20;
    expect_povray(mandel, {0, 0.1f, 1, 0.4f, 1, 1, 1, 0.05f});
    expect_povray(mandel, {0, 0, 1, 0.1f, 0.05f, 0.15f, 1, 0}, 0.6f);
    PatternSpec spiral1 = spec_of(PatternKind::spiral1);
    spiral1.arms = 3;
    expect_povray(spiral1,
                  {0.0578f, 0.8719f, 0.0709f, 0.9266f, 0.0991f, 0.0700f, 0.6644f, 0.2476f});
    PatternSpec spiral2 = spec_of(PatternKind::spiral2);
    spiral2.arms = 5;
    expect_povray(spiral2,
                  {0.3315f, 0.4945f, 0.4680f, 0.9972f, 0.0175f, 0.4945f, 0.9974f, 0.2869f});
}

// The wave patterns are rings round the wave sources: ripples' mean of sin(2 pi d) over them
// mapped to [0, 1], waves' weighted by 1 / frequency, 0.2 (2.5 + mean) as POV-Ray maps them.
TEST(Pattern, RipplesAndWavesAreRingsRoundTheSources) {
    const Point3 p{0.3f, -1.2f, 2.1f};
    double ripples = 0, waves = 0;
    for (const WaveSource& s : wave_sources()) {
        const double d = length(p - to_point(s.at));
        ripples += std::sin(2 * std::acos(-1.0) * d);
        waves += std::sin(2 * std::acos(-1.0) * d * s.frequency) / s.frequency;
    }
    EXPECT_EQ(wave_sources().size(), 10u);
    EXPECT_NEAR(pattern_value(spec_of(PatternKind::ripples), p), 0.5 * (1 + ripples / 10), 1e-5);
    EXPECT_NEAR(pattern_value(spec_of(PatternKind::waves), p), 0.2 * (2.5 + waves / 10), 1e-5);
    for (const WaveSource& s : wave_sources()) {
        EXPECT_NEAR(length(s.at), 1, 1e-6f);
        EXPECT_GE(s.frequency, 0.01f);
        EXPECT_LE(s.frequency, 1.01f);
    }
}

// wrinkles sums noise in [0, 1] over ten octaves, halving: half that sum lies in [0, 1).
TEST(Pattern, WrinklesStayInRange) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(-50, 50);
    float lowest = 1, highest = 0;
    for (int i = 0; i < 2000; ++i) {
        const float v = pattern_value(spec_of(PatternKind::wrinkles), {u(rng), u(rng), u(rng)});
        lowest = std::min(lowest, v);
        highest = std::max(highest, v);
    }
    EXPECT_GE(lowest, 0);
    EXPECT_LT(highest, 1);
    EXPECT_LT(lowest, 0.4f);  // it varies
    EXPECT_GT(highest, 0.6f);
}

// The list patterns at points of their own: hexagon rgb 0, rgb 0.5, rgb 1 and brick rgb 0, rgb 1
// (mortar 0, brick 1) as POV-Ray's eval_pigment gives them.
TEST(Pattern, HexagonAndBrickGivePovRaysValues) {
    const Point3 hexagon_points[] = {{0, 0, 0},           {0.2f, 0, 1.5f},  {1.5f, 0, 0.8f},
                                     {-1.4f, 0.3f, 0.9f}, {2.9f, 0, -2.1f}, {0.7f, 0, 3.3f},
                                     {-3.1f, 0, -4.4f},   {4.6f, 0, 1.2f}};
    const float hexagon_povray[] = {0, 0.5f, 1, 1, 1, 1, 0, 1};
    for (int i = 0; i < 8; ++i)
        EXPECT_EQ(pattern_value(spec_of(PatternKind::hexagon), hexagon_points[i]),
                  hexagon_povray[i])
            << "point " << i;
    // Courses 3 high, bricks 8 by 4.5, mortar 0.5: (1, -0.5, 1) lies in a course's mortar,
    // (-0.5, 1, 1) in a joint between bricks, (-0.5, 4, 1) in a brick of the next course.
    const Point3 brick_points[] = {{1, 1, 1},     {1, -0.5f, 1}, {-0.5f, 1, 1},
                                   {-0.5f, 4, 1}, {5, 2, 3},     {-7.2f, -2.7f, 9.9f}};
    const float brick_povray[] = {1, 0, 0, 1, 1, 1};
    for (int i = 0; i < 6; ++i)
        EXPECT_EQ(pattern_value(spec_of(PatternKind::brick), brick_points[i]), brick_povray[i])
            << "point " << i;
    // Along z through the hexagons' centres (0, 0, sqrt(3) k): the colours cycle 0, 1/2, 1.
    for (int k = -3; k <= 3; ++k) {
        const float expected = float(((k % 3) + 3) % 3) / 2;
        EXPECT_EQ(pattern_value(spec_of(PatternKind::hexagon), {0, 0, 1.7320508f * float(k)}),
                  expected)
            << k;
    }
}

// Along x at -1.96875 + k / 4 (pixels of a 64-pixel render of a plane), as POV-Ray rendered them.
TEST(Pattern, GradientWavesFrequencyAndPhase) {
    PatternSpec gradient = spec_of(PatternKind::gradient);
    const Point3 p{-1.96875f, -0.03125f, 0};  // the fraction of x: 1/32
    EXPECT_NEAR(pattern_value(gradient, p), 0.03125f, 1e-6);
    EXPECT_NEAR(pattern_value(gradient, {-1.71875f, 0, 0}), 0.28125f, 1e-6);
    const auto wave = [&](PatternWave w, float exponent = 1) {
        PatternSpec s = gradient;
        s.wave = w;
        s.exponent = exponent;
        return pattern_value(s, p);
    };
    EXPECT_NEAR(wave(PatternWave::triangle), 0.0625f, 1e-6);
    EXPECT_NEAR(wave(PatternWave::sine), 0.598f, 1e-3);
    EXPECT_NEAR(wave(PatternWave::scallop), 0.098f, 1e-3);
    EXPECT_NEAR(wave(PatternWave::cubic), 0.003f, 1e-3);
    EXPECT_NEAR(wave(PatternWave::poly, 2), 0.001f, 1e-3);
    PatternSpec shifted = gradient;
    shifted.frequency = 2;
    shifted.phase = 0.25f;
    EXPECT_NEAR(pattern_value(shifted, p), 0.3125f, 1e-6);
    // Marble is gradient x through the triangle wave; onion the distance from the origin.
    EXPECT_NEAR(pattern_value(spec_of(PatternKind::marble), {-1.46875f, 0, 0}), 0.9375f, 1e-6);
    EXPECT_NEAR(pattern_value(spec_of(PatternKind::onion), {-1.96875f, 0, 0}), 0.96875f, 1e-6);
    EXPECT_NEAR(pattern_value(spec_of(PatternKind::leopard), p), 0.101f, 1e-3);
    // 1 stays 1, as POV-Ray keeps it: planar's top is the map's end, not its start.
    EXPECT_EQ(pattern_value(spec_of(PatternKind::planar), {0, 0, 0}), 1.0f);
}

TEST(Pattern, NoiseKindsStayInRangeAndAreTheSameEachTime) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(-50, 50);
    for (const PatternKind kind :
         {PatternKind::agate, PatternKind::bozo, PatternKind::crackle, PatternKind::granite}) {
        double sum = 0;
        float low = 1, high = 0;
        for (int i = 0; i < 4000; ++i) {
            const Point3 p{u(rng), u(rng), u(rng)};
            const float v = pattern_value(spec_of(kind), p);
            ASSERT_GE(v, 0.0f);
            ASSERT_LE(v, 1.0f);
            ASSERT_EQ(v, pattern_value(spec_of(kind), p));
            sum += v;
            low = std::min(low, v);
            high = std::max(high, v);
        }
        // Each spreads over a good part of the map (granite's values sit low, as POV-Ray's).
        EXPECT_GT(high - low, 0.3f) << int(kind);
        EXPECT_GT(sum / 4000, 0.05) << int(kind);
    }
    EXPECT_EQ(pattern_value(spec_of(PatternKind::crackle), {1e30f, 0, 0}), 0.0f);
    EXPECT_EQ(pattern_value(spec_of(PatternKind::gradient), {NAN, 0, 0}), 0.0f);
}

TEST(Pattern, TurbulenceMovesThePointAndKeepsTheRange) {
    PatternSpec calm = spec_of(PatternKind::gradient);
    PatternSpec stirred = calm;
    stirred.turbulence = {0.5f, 0.5f, 0.5f};
    int moved = 0;
    for (int i = 0; i < 100; ++i) {
        const Point3 p{0.137f * float(i), 0.3f, 0.71f * float(i)};
        const float v = pattern_value(stirred, p);
        EXPECT_GE(v, 0.0f);
        EXPECT_LE(v, 1.0f);
        moved += std::abs(v - pattern_value(calm, p)) > 1e-3f;
    }
    EXPECT_GT(moved, 80);
}

}  // namespace
}  // namespace glint
