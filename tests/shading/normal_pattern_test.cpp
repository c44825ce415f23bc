// POV-Ray's normal patterns: the slope of a pattern by its tetrahedral differences with worked
// numbers, the tilt they give a normal, and what the tilt keeps (unit length, the side of the
// surface, the depth under scaling).
#include "glint/shading/normal_pattern.h"

#include <gtest/gtest.h>

#include <cmath>

#include "glint/shading/noise.h"

namespace glint::normal_pattern_test {
namespace {

NormalPattern gradient_x(float amount) {
    NormalPattern np;
    np.kind = NormalPatternKind::slope;
    np.pattern.kind = PatternKind::gradient;
    np.pattern.direction = {1, 0, 0};
    np.amount = amount;
    return np;
}

void expect_near(Vector3 a, Vector3 b, float tolerance) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

// f = x: sum over the corners v of f(q + h v) v = h sum v v.x = (4/3) h x-axis, times
// -5 amount 0.02 / h: -(2/15) amount along x, whatever the step.
TEST(NormalPattern, SlopeOfARampIsTwoFifteenthsOfTheAmountDownhill) {
    NormalPattern np = gradient_x(1);
    expect_near(normal_offset(np, {0.5f, 0.2f, -0.3f}), {-2.0f / 15, 0, 0}, 1e-5f);
    np.accuracy = 0.005f;
    expect_near(normal_offset(np, {0.5f, 0.2f, -0.3f}), {-2.0f / 15, 0, 0}, 1e-4f);
    np.amount = 3;
    expect_near(normal_offset(np, {0.5f, 0.2f, -0.3f}), {-0.4f, 0, 0}, 3e-4f);
}

// POV-Ray's pigment_pattern: a ramp from black to red, green or white along x has the grey
// 0.297 x, 0.589 x or x, and its slope is that much of the pattern's own.
TEST(NormalPattern, SlopeOfAPigmentsGreyWeighsItsChannels) {
    for (const auto& [top, grey] :
         {std::pair{Color{1, 0, 0}, 0.297f}, std::pair{Color{0, 1, 0}, 0.589f},
          std::pair{Color{1, 1, 1}, 1.0f}}) {
        auto ramp = std::make_shared<PatternTexture>();
        ramp->spec.kind = PatternKind::gradient;
        ramp->spec.direction = {1, 0, 0};
        ramp->colors = {{0, Color{0, 0, 0}}, {1, top}};
        NormalPattern np;
        np.kind = NormalPatternKind::slope;
        np.pigment = std::make_shared<const Texture>(PatternTexturePtr(ramp));
        np.amount = 1;
        expect_near(normal_offset(np, {0.5f, 0.2f, -0.3f}), {-2.0f / 15 * grey, 0, 0}, 1e-5f);
    }
}

// (0, 1, 0) + (-2/15, 0, 0), normalised: (-0.132164, 0.991228, 0).
TEST(NormalPattern, TiltIsTheNormalPlusTheOffsetNormalised) {
    const Normal3 n = perturbed(gradient_x(1), {0, 1, 0}, {0.5f, 0, 0});
    expect_near(to_vector(n), {-0.132164f, 0.991228f, 0}, 1e-5f);
}

// POV-Ray's bumps keep their depth when the pattern is scaled (unless no_bump_scale).
TEST(NormalPattern, ScalingThePatternScalesItsDetailNotItsDepth) {
    NormalPattern small;
    small.kind = NormalPatternKind::bumps;
    NormalPattern large = small;
    large.to_pattern = Transform::scale(0.5f, 0.5f, 0.5f);
    for (const Point3 q : {Point3{0.3f, 0.1f, 0.7f}, Point3{-1.2f, 0.4f, 2.5f}}) {
        const Normal3 a = perturbed(small, {0, 0, 1}, q);
        const Normal3 b = perturbed(large, {0, 0, 1}, {2 * q.x, 2 * q.y, 2 * q.z});
        expect_near(to_vector(a), to_vector(b), 1e-5f);
    }
}

TEST(NormalPattern, BumpsAreTheVectorNoiseTimesTheAmount) {
    NormalPattern np;
    np.kind = NormalPatternKind::bumps;
    const Point3 q{0.37f, 1.21f, -0.52f};
    const Vector3 half = normal_offset(np, q);
    np.amount = 1;
    expect_near(normal_offset(np, q), half * 2, 1e-6f);
    // Rescaled from glint's noise to the spread of POV-Ray's.
    expect_near(half, vector_noise(q) * (0.5f * 1.2f), 1e-6f);
}

TEST(NormalPattern, WrinklesLeanTowardsPositiveAxes) {
    NormalPattern np;
    np.kind = NormalPatternKind::wrinkles;
    const Vector3 v = normal_offset(np, {0.31f, 0.77f, 0.13f});
    EXPECT_GT(v.x, 0);
    EXPECT_GT(v.y, 0);
    EXPECT_GT(v.z, 0);
}

// Ripples are rings: nearly radial offsets, the same at the same phase along each ring.
TEST(NormalPattern, RipplesRepeatWithTheirFrequency) {
    NormalPattern np;
    np.kind = NormalPatternKind::ripples;
    np.amount = 1;
    const Vector3 a = normal_offset(np, {40, 0, 0});
    np.pattern.phase = 1;  // a whole wave on: the same rings
    expect_near(normal_offset(np, {40, 0, 0}), a, 1e-4f);
    np.pattern.phase = 0.5f;  // half a wave on: the rings turned over
    expect_near(normal_offset(np, {40, 0, 0}), a * -1, 1e-3f);
}

TEST(NormalPattern, ATiltStaysUnitAndOnItsSide) {
    for (const NormalPatternKind kind :
         {NormalPatternKind::bumps, NormalPatternKind::dents, NormalPatternKind::wrinkles,
          NormalPatternKind::ripples, NormalPatternKind::waves, NormalPatternKind::slope}) {
        NormalPattern np = gradient_x(1e6f);
        np.kind = kind;
        np.to_pattern = Transform::scale(50, 1, 0.02f);
        for (int i = 0; i < 50; ++i) {
            const Point3 p{0.13f * i, -0.07f * i, 0.05f * i};
            const Normal3 n = normalize(Normal3{0.3f, 1, -0.2f});
            const Normal3 t = perturbed(np, n, p);
            EXPECT_NEAR(length(to_vector(t)), 1, 1e-5f);
            EXPECT_GT(dot(to_vector(t), to_vector(n)), 0);
        }
    }
}

TEST(NormalPattern, NothingToAddLeavesTheNormal) {
    NormalPattern np = gradient_x(0);
    const Normal3 n = normalize(Normal3{1, 2, 3});
    expect_near(to_vector(perturbed(np, n, {0.4f, 0, 0})), to_vector(n), 1e-6f);
    np.amount = 1;
    expect_near(to_vector(perturbed(np, n, {NAN, 0, 0})), to_vector(n), 1e-6f);
}

}  // namespace
}  // namespace glint::normal_pattern_test
