// Fog against worked numbers: constant fog's exp(-d / distance), ground fog's atan integral
// (checked against numerical integration too), filter, transmit and several fogs together.
#include "glint/shading/fog.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "glint/math/interval.h"

namespace glint::fog_test {

constexpr double kPi = std::numbers::pi;

void expect_near(Color a, Color b, float tol = 1e-5f) {
    EXPECT_NEAR(a.r, b.r, tol);
    EXPECT_NEAR(a.g, b.g, tol);
    EXPECT_NEAR(a.b, b.b, tol);
}

Fog ground_fog(float distance = 1) {
    Fog fog;
    fog.kind = FogKind::ground;
    fog.distance = distance;
    fog.offset = 0;
    fog.altitude = 1;
    return fog;
}

TEST(Fog, ConstantFogFadesTheColourBehindByExpOfDistance) {
    // 5 units through fog of distance 10: T = exp(-0.5) = 0.606531; the red behind arrives as
    // 0.606531 (1, 0, 0) + 0.393469 (0.5, 0.5, 0.5) = (0.803265, 0.196735, 0.196735).
    Fog fog;
    fog.distance = 10;
    const std::vector<Fog> fogs{fog};
    const Ray ray{{0, 0, 0}, {0, 0, 1}};
    EXPECT_NEAR(optical_depth(fog, ray, 5), 0.5, 1e-12);
    const FogEffect e = fog_effect(fogs, ray, 5);
    expect_near(e.transmittance, Color::gray(0.606531f));
    expect_near(through(e, {1, 0, 0}), {0.803265f, 0.196735f, 0.196735f});
}

TEST(Fog, TheSkyBehindFogIsTheFogsColour) {
    Fog fog;
    fog.distance = 10;
    fog.color = {0.2f, 0.3f, 0.4f};
    const std::vector<Fog> fogs{fog};
    const FogEffect e = fog_effect(fogs, {{0, 0, 0}, {0, 0, 1}}, kInfinity);
    expect_near(through(e, {5, 5, 5}), {0.2f, 0.3f, 0.4f});
}

TEST(Fog, TransmitIsTheLeastThatGetsThroughAndFilterTintsIt) {
    Fog fog;
    fog.distance = 1;
    fog.color = {1, 0.5f, 0};
    fog.transmit = 0.3f;
    std::vector<Fog> fogs{fog};
    const Ray ray{{0, 0, 0}, {1, 0, 0}};
    // Endless: exp(-inf) = 0 < 0.3, so 0.3 gets through and the fog adds 0.7 of its colour.
    FogEffect e = fog_effect(fogs, ray, kInfinity);
    expect_near(e.transmittance, Color::gray(0.3f));
    expect_near(e.added, {0.7f, 0.35f, 0});
    // Fully filtering: what gets through takes the fog's colour, 0.3 (1, 0.5, 0).
    fogs[0].filter = 1;
    e = fog_effect(fogs, ray, kInfinity);
    expect_near(e.transmittance, {0.3f, 0.15f, 0});
}

TEST(Fog, SeveralFogsMultiplyTheirTransmittancesAndAddTheirColours) {
    Fog a, b;
    a.distance = 2, a.color = {1, 0, 0};
    b.distance = 4, b.color = {0, 0, 1};
    const std::vector<Fog> fogs{a, b};
    // Length 2: T_a = exp(-1) = 0.367879, T_b = exp(-0.5) = 0.606531.
    const FogEffect e = fog_effect(fogs, {{0, 0, 0}, {0, 1, 0}}, 2);
    expect_near(e.transmittance, Color::gray(0.367879f * 0.606531f));
    expect_near(e.added, {0.632121f, 0, 0.393469f});
}

TEST(Fog, GroundFogIsFullBelowItsOffsetAndThinsAsOneOverOnePlusHSquared) {
    const Fog fog = ground_fog();
    // Level, 4 long: at height -1 the density is 1; at height 1 it is 1 / (1 + 1) = 0.5.
    EXPECT_NEAR(optical_depth(fog, {{0, -1, 0}, {1, 0, 0}}, 4), 4, 1e-9);
    EXPECT_NEAR(optical_depth(fog, {{0, 1, 0}, {1, 0, 0}}, 4), 2, 1e-6);
    // Straight up from the ground to height 1: atan(1) = pi / 4; from -1 to 1: 1 + pi / 4.
    EXPECT_NEAR(optical_depth(fog, {{0, 0, 0}, {0, 1, 0}}, 1), kPi / 4, 1e-9);
    EXPECT_NEAR(optical_depth(fog, {{0, -1, 0}, {0, 1, 0}}, 2), 1 + kPi / 4, 1e-9);
    // Downwards from height 1 to -1: the same stretch the other way.
    EXPECT_NEAR(optical_depth(fog, {{0, 1, 0}, {0, -1, 0}}, 2), 1 + kPi / 4, 1e-9);
    // At 45 degrees from the ground to height 1, sqrt(2) long: sqrt(2) pi / 4 = 1.110721.
    const float s = std::sqrt(0.5f);
    EXPECT_NEAR(optical_depth(fog, {{0, 0, 0}, {s, s, 0}}, std::sqrt(2.0)), 1.110721, 1e-5);
    // Endless upwards the integral converges to pi / 2; level or down it never ends.
    EXPECT_NEAR(optical_depth(fog, {{0, 0, 0}, {0, 1, 0}}, kInfinity), kPi / 2, 1e-9);
    EXPECT_EQ(optical_depth(fog, {{0, 5, 0}, {1, 0, 0}}, kInfinity), kInfinity);
    EXPECT_EQ(optical_depth(fog, {{0, 5, 0}, {0, -1, 0}}, kInfinity), kInfinity);
}

TEST(Fog, GroundFogFollowsItsOffsetAltitudeUpAndDistance) {
    Fog fog = ground_fog(2);
    fog.offset = 3, fog.altitude = 2, fog.up = {0, 0, 1};
    // Along x at z = 5: h = (5 - 3) / 2 = 1, density 0.5; 4 long over distance 2: 1.
    EXPECT_NEAR(optical_depth(fog, {{0, 0, 5}, {1, 0, 0}}, 4), 1, 1e-6);
}

TEST(Fog, GroundFogMatchesNumericalIntegrationOnRandomStretches) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(-1, 1);
    Fog fog = ground_fog(3);
    fog.offset = 0.5f, fog.altitude = 1.5f;
    for (int i = 0; i < 200; ++i) {
        const Point3 o{u(rng) * 4, u(rng) * 4, u(rng) * 4};
        Vector3 d{u(rng), u(rng), u(rng)};
        d = d / length(d);
        const double len = 10 * (u(rng) + 1);
        double sum = 0;
        const int steps = 20000;
        for (int k = 0; k < steps; ++k) {
            const double y = o.y + d.y * (k + 0.5) * len / steps;
            const double h = (y - fog.offset) / fog.altitude;
            sum += (h <= 0 ? 1 : 1 / (1 + h * h)) * len / steps;
        }
        EXPECT_NEAR(optical_depth(fog, {o, d}, len), sum / fog.distance, 1e-4) << i;
    }
}

TEST(Fog, TurbulenceThinsNearFogAndLeavesDistantFogAlone) {
    Fog fog;
    fog.distance = 10;
    fog.turbulence = {1, 1, 1};
    fog.turbulence_depth = 0.5f;
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(-5, 5);
    bool thinned = false;
    for (int i = 0; i < 50; ++i) {
        const Ray ray{{u(rng), u(rng), u(rng)}, {0, 0, 1}};
        const double len = 4;
        const double tau = optical_depth(fog, ray, len);
        // Never thicker, and thinner by at most exp(-len / distance) of it.
        EXPECT_LE(tau, len / fog.distance + 1e-12);
        EXPECT_GE(tau, len / fog.distance * (1 - std::exp(-len / fog.distance)) - 1e-12);
        thinned |= tau < len / fog.distance - 1e-6;
    }
    EXPECT_TRUE(thinned);
    fog.turbulence_depth = 0;
    EXPECT_NEAR(optical_depth(fog, {{1, 2, 3}, {0, 0, 1}}, 4), 0.4, 1e-12);
}

}  // namespace glint::fog_test
