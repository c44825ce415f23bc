#include "glint/shading/medium.h"

#include <gtest/gtest.h>

#include <cmath>

#include "glint/math/interval.h"

namespace glint {
namespace {

// The mean of the phase function over the sphere: over cos theta, uniform in [-1, 1].
float mean_over_sphere(PhaseKind kind, float g) {
    constexpr int kSteps = 200000;
    double sum = 0;
    for (int i = 0; i < kSteps; ++i)
        sum += phase_value(kind, g, -1 + 2 * (float(i) + 0.5f) / kSteps);
    return float(sum / kSteps);
}

TEST(Medium, EveryPhaseFunctionAveragesOneOverTheSphere) {
    for (const PhaseKind kind :
         {PhaseKind::isotropic, PhaseKind::rayleigh, PhaseKind::mie_hazy, PhaseKind::mie_murky})
        EXPECT_NEAR(mean_over_sphere(kind, 0), 1, 1e-4f);
    for (const float g : {-0.6f, 0.f, 0.3f, 0.8f})
        EXPECT_NEAR(mean_over_sphere(PhaseKind::henyey_greenstein, g), 1, 2e-3f) << g;
}

TEST(Medium, PhaseFunctionsHaveTheirWorkedValues) {
    EXPECT_EQ(phase_value(PhaseKind::isotropic, 0, 0.3f), 1);
    // Rayleigh: 3/4 (1 + cos^2): 1.5 forwards and backwards, 0.75 sideways.
    EXPECT_FLOAT_EQ(phase_value(PhaseKind::rayleigh, 0, 1), 1.5f);
    EXPECT_FLOAT_EQ(phase_value(PhaseKind::rayleigh, 0, 0), 0.75f);
    // Mie hazy forwards: (1 + 9) / 2; sideways u = 1/2: (1 + 9 / 256) / 2.
    EXPECT_FLOAT_EQ(phase_value(PhaseKind::mie_hazy, 0, 1), 5);
    EXPECT_FLOAT_EQ(phase_value(PhaseKind::mie_hazy, 0, 0), 0.5f * (1 + 9.f / 256));
    // Mie murky forwards: 33/83 * 51.
    EXPECT_FLOAT_EQ(phase_value(PhaseKind::mie_murky, 0, 1), 33.f / 83 * 51);
    // Henyey-Greenstein with g = 0.5: forwards (1 - 0.25) / 0.5^3 = 6, backwards 0.75 / 1.5^3.
    EXPECT_FLOAT_EQ(phase_value(PhaseKind::henyey_greenstein, 0.5f, 1), 6);
    EXPECT_FLOAT_EQ(phase_value(PhaseKind::henyey_greenstein, 0.5f, -1), 0.75f / 3.375f);
}

TEST(Medium, TheDensityIsTheProductOfItsFactors) {
    Medium m;
    EXPECT_EQ(density_at(m, {1, 2, 3}), (Color{1, 1, 1}));
    m.density = {Texture(Color{0.5f, 1, 0.2f}), Texture(Color{0.5f, 0.5f, 1})};
    EXPECT_EQ(density_at(m, {1, 2, 3}), (Color{0.25f, 0.5f, 0.2f}));
    // sigma_t = d (absorption + extinction scattering).
    m.absorption = {1, 2, 3};
    m.scattering = {2, 2, 2};
    m.extinction = 0.5f;
    EXPECT_EQ(extinction_of(m, {0.5f, 1, 2}), (Color{1, 3, 8}));
}

TEST(Medium, NumbersOutsideTheirRangesAreNamed) {
    Medium m;
    EXPECT_EQ(describe_problem(m), "");
    m.scattering = {1, -0.1f, 0};
    EXPECT_EQ(describe_problem(m), "medium scattering must be finite and >= 0");
    m.scattering = {};
    m.emission = {kInfinity, 0, 0};
    EXPECT_EQ(describe_problem(m), "medium emission must be finite and >= 0");
    m.emission = {};
    m.eccentricity = 1;
    EXPECT_EQ(describe_problem(m), "medium eccentricity must be in (-1, 1)");
    m.eccentricity = 0;
    m.samples = 0;
    EXPECT_EQ(describe_problem(m), "medium samples must be from 1 to 1000");
}

}  // namespace
}  // namespace glint
