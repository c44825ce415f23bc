// Refraction between media: the stack of media a ray travels through, and Snell's law at a
// glass-water boundary in a rendered ray tree.
#include "glint/render/integrators/medium_stack.h"

#include <gtest/gtest.h>

#include <cmath>

#include "glint/render/integrators/whitted.h"

namespace glint {
namespace {

// Materials only identify media here; their contents do not matter.
const Material kGlass, kAir, kWater, kOther;

TEST(MediumStack, AnAirBubbleInGlassHasGlassOnBothSides) {
    const MediumStack vacuum;
    EXPECT_EQ(vacuum.ior(), 1);
    const MediumCrossing into_glass = vacuum.enter(7, &kGlass, 1.5f);
    EXPECT_EQ(into_glass.n1, 1);
    EXPECT_EQ(into_glass.n2, 1.5f);
    const MediumCrossing into_bubble = into_glass.after.enter(9, &kAir, 1.0f);
    EXPECT_EQ(into_bubble.n1, 1.5f);
    EXPECT_EQ(into_bubble.n2, 1);
    const MediumCrossing out_of_bubble = into_bubble.after.leave(9, &kAir, 1.0f);
    EXPECT_EQ(out_of_bubble.n1, 1);
    EXPECT_EQ(out_of_bubble.n2, 1.5f);
    const MediumCrossing out_of_glass = out_of_bubble.after.leave(7, &kGlass, 1.5f);
    EXPECT_EQ(out_of_glass.n1, 1.5f);
    EXPECT_EQ(out_of_glass.n2, 1);
    EXPECT_EQ(out_of_glass.after.size(), 0);
}

TEST(MediumStack, OverlappingObjectsLeaveInAnyOrder) {
    // Into A (1.3), into B (1.6), out of A: the ray is still in B.
    const MediumCrossing out_of_a = MediumStack()
                                        .enter(1, &kWater, 1.3f)
                                        .after.enter(2, &kGlass, 1.6f)
                                        .after.leave(1, &kWater, 1.3f);
    EXPECT_EQ(out_of_a.n1, 1.3f);
    EXPECT_EQ(out_of_a.n2, 1.6f);
    EXPECT_EQ(out_of_a.after.size(), 1);
}

TEST(MediumStack, LeavingAnObjectNeverEnteredGoesIntoTheCurrentMedium) {
    // A ray that started inside glass (the camera in it) leaves to vacuum, as Whitted's tracer
    // always assumed; one inside water that leaves such glass passes into water.
    EXPECT_EQ(MediumStack().leave(3, &kGlass, 1.5f).n2, 1);
    const MediumCrossing c = MediumStack().enter(1, &kWater, 1.33f).after.leave(3, &kGlass, 1.5f);
    EXPECT_EQ(c.n1, 1.5f);
    EXPECT_EQ(c.n2, 1.33f);
    EXPECT_EQ(c.after.size(), 1);
}

TEST(MediumStack, NestingDeeperThanItsCapacityKeepsTheOuterMedia) {
    MediumStack s;
    for (int i = 0; i < MediumStack::kCapacity + 3; ++i)
        s = s.enter(i, &kOther, 1 + 0.1f * i).after;
    EXPECT_EQ(s.size(), MediumStack::kCapacity);
    EXPECT_FLOAT_EQ(s.ior(), 1 + 0.1f * (MediumStack::kCapacity - 1));
}

TEST(MediumStack, AnObjectOfSeparateFacesIsLeftThroughAnotherFace) {
    // Into a glass prism through face 4, out through face 5 (the same glass): back in water.
    const MediumCrossing out = MediumStack()
                                   .enter(1, &kWater, 1.33f)
                                   .after.enter(4, &kGlass, 1.5f)
                                   .after.leave(5, &kGlass, 1.5f);
    EXPECT_EQ(out.n2, 1.33f);
    EXPECT_EQ(out.after.size(), 1);
}

// Water (n = 1.333) from y = 2 down, with a glass block (n = 1.5) inside it from y = 1 down,
// and a thin emitting strip inside the glass at y = 0 around x = strip_x. A ray from (0, 3, 0)
// at 45 degrees enters the water at x = 1.
Scene glass_in_water(float strip_x) {
    Scene scene;
    scene.settings.background = Color{};
    scene.settings.max_depth = 10;
    Material clear;
    clear.ka = clear.kd = clear.ks = 0;
    clear.transmit = 1;
    Material water = clear, glass = clear;
    water.ior = 1.333f;
    glass.ior = 1.5f;
    Material strip;
    strip.ka = strip.kd = 0;
    strip.emission = Color::gray(1);
    scene.materials = {water, glass, strip};
    scene.objects.push_back({Box{{-10, -5, -10}, {10, 2, 10}}, 0});
    scene.objects.push_back({Box{{-9, -4, -9}, {9, 1, 9}}, 1});
    scene.objects.push_back({Box{{strip_x - 0.03f, -0.01f, -1}, {strip_x + 0.03f, 0, 1}}, 2});
    return scene;
}

// Where the ray meets y = 0 when each boundary obeys n1 sin(theta1) = n2 sin(theta2) down from
// sin 45 in vacuum, the water layer 1 deep, then the glass layer 1 deep.
float landing_x(float n_water_above_glass) {
    const float s = std::sqrt(0.5f);
    const float sin_water = s / 1.333f;
    const float sin_glass = sin_water * n_water_above_glass / 1.5f;
    const auto tan_of = [](float sine) { return sine / std::sqrt(1 - sine * sine); };
    return 1 + tan_of(sin_water) + tan_of(sin_glass);
}

TEST(MediumStack, SnellsLawAtAGlassWaterBoundaryUsesBothIndices) {
    // With water above the glass, n sin(theta) stays sin 45 through the layers: the ray lands
    // at x = 1 + 0.62577 + 0.53452. Had the glass been entered from vacuum (the old
    // assumption), it would land at 1 + 0.62577 + 0.37808, 0.156 to the left.
    const float right = landing_x(1.333f), vacuum_assumed = landing_x(1);
    EXPECT_NEAR(right, 2.16029f, 1e-4f);
    EXPECT_NEAR(vacuum_assumed, 2.00385f, 1e-4f);
    const Ray ray{{0, 3, 0}, normalize(Vector3{1, -1, 0})};
    RayStats stats;
    EXPECT_EQ(WhittedIntegrator(World(glass_in_water(right))).trace(ray, 1, 1, stats).r, 1);
    EXPECT_EQ(WhittedIntegrator(World(glass_in_water(vacuum_assumed))).trace(ray, 1, 1, stats).r,
              0);
}

}  // namespace
}  // namespace glint
