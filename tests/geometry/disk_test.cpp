#include "glint/geometry/disk.h"

#include <gtest/gtest.h>

#include <cmath>

#include "glint/geometry/axis_frame.h"
#include "shape_property_checks.h"

namespace glint {
namespace {

using testing::expect_shape_properties;
using testing::PropertyOptions;
using testing::RandomRays;

TEST(Disk, WorkedHitFromAbove) {
    const Disk disk{{0, 1, 0}, {0, 1, 0}, 2};
    const Ray ray{{0.5f, 5, 0.5f}, {0, -1, 0}};
    const auto hit = disk.intersect(ray, {});
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit->t, 4);
    const SurfacePoint sp = disk.surface_at(ray, *hit);
    EXPECT_EQ(sp.p, (Point3{0.5f, 1, 0.5f}));
    EXPECT_EQ(sp.normal, (Normal3{0, 1, 0}));
    EXPECT_EQ(sp.shading_normal, sp.normal);
    // rho = sqrt(0.5) = 0.70711 of radius 2; the angle of (0.5, 0, 0.5) from +x towards -z is
    // -45 degrees, i.e. 315 degrees: u = 0.875.
    EXPECT_NEAR(sp.uv.x, 0.875f, 1e-6f);
    EXPECT_NEAR(sp.uv.y, 0.35355339f, 1e-6f);
}

TEST(Disk, IsTwoSidedAndKeepsItsFrontNormal) {
    const Disk disk{{0, 1, 0}, {0, 1, 0}, 2};
    const Ray ray{{0.5f, -3, 0}, {0, 1, 0}};
    const auto hit = disk.intersect(ray, {});
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit->t, 4);
    EXPECT_EQ(disk.surface_at(ray, *hit).normal, (Normal3{0, 1, 0}));  // not flipped here
}

TEST(Disk, RadiusAndHoleLimitTheHits) {
    const Disk annulus{{0, 0, 0}, {0, 0, 1}, 2, 1};
    const auto hit_at = [&](float x) { return annulus.intersect({{x, 0, -3}, {0, 0, 1}}, {}); };
    EXPECT_FALSE(hit_at(0));      // the hole's centre
    EXPECT_FALSE(hit_at(0.99f));  // still in the hole
    EXPECT_TRUE(hit_at(1.01f));
    EXPECT_TRUE(hit_at(1.99f));
    EXPECT_FALSE(hit_at(2.01f));  // past the rim
    const Ray ray{{1.5f, 0, -3}, {0, 0, 1}};
    // v runs from the inner edge (0) to the rim (1): (1.5 - 1) / (2 - 1).
    EXPECT_NEAR(annulus.surface_at(ray, *annulus.intersect(ray, {})).uv.y, 0.5f, 1e-6f);
}

TEST(Disk, ParallelRaysAndRaysOutsideTheIntervalMiss) {
    const Disk disk{{0, 0, 0}, {0, 1, 0}, 1};
    EXPECT_FALSE(disk.intersect({{-5, 0.5f, 0}, {1, 0, 0}}, {}));
    EXPECT_FALSE(disk.intersect({{-5, 0, 0}, {1, 0, 0}}, {}));  // in the plane
    EXPECT_FALSE(disk.intersect({{0, 2, 0}, {0, -1, 0}}, {0, 1.5f}));
    EXPECT_FALSE(disk.intersect({{0, 2, 0}, {0, 1, 0}}, {}));  // behind
}

TEST(Disk, TiltedDiskUsesItsNormalisedNormal) {
    // A normal of length 2: the disk normalises it where it matters.
    const Disk disk{{1, 1, 1}, {0, 0, 2}, 1};
    const Ray ray{{1.5f, 1, 5}, {0, 0, -1}};
    const auto hit = disk.intersect(ray, {});
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit->t, 4);
    EXPECT_EQ(disk.surface_at(ray, *hit).normal, (Normal3{0, 0, 1}));
}

TEST(Disk, BoundsAreTightForTiltedDisks) {
    const Bounds3 flat = Disk{{0, 0, 0}, {0, 1, 0}, 2}.bounds();
    EXPECT_NEAR(flat.min.x, -2, 1e-5f);
    EXPECT_NEAR(flat.max.z, 2, 1e-5f);
    EXPECT_EQ(flat.min.y, 0);
    EXPECT_EQ(flat.max.y, 0);
    // Normal (1, 1, 0) / sqrt 2: extents 2 sqrt(1 - n_i^2) = sqrt 2 along x and y, 2 along z.
    const Bounds3 tilted = Disk{{0, 0, 0}, Normal3(normalize(Vector3{1, 1, 0})), 2}.bounds();
    EXPECT_NEAR(tilted.max.x, std::sqrt(2.0f), 1e-5f);
    EXPECT_NEAR(tilted.max.y, std::sqrt(2.0f), 1e-5f);
    EXPECT_NEAR(tilted.max.z, 2, 1e-5f);
}

TEST(Disk, FarRaysStayAccurate) {
    const Disk disk{{0, 0, 0}, Normal3(normalize(Vector3{0.3f, 1, 0.2f})), 1};
    const Ray ray{{-1e4f, 30, 20}, normalize(Vector3{1e4f, -30, -20})};
    const auto hit = disk.intersect(ray, {});
    ASSERT_TRUE(hit);
    const SurfacePoint sp = disk.surface_at(ray, *hit);
    EXPECT_NEAR(distance(sp.p, {0, 0, 0}), 0, 2e-3f);
}

TEST(AxisFrame, IsTheWorldFrameForAxisYAndRightHandedForOthers) {
    const AxisFrame y = axis_frame({0, 1, 0});
    EXPECT_EQ(y.x, (Vector3{1, 0, 0}));
    EXPECT_EQ(y.z, (Vector3{0, 0, 1}));
    for (const Vector3 axis :
         {Vector3{0, -1, 0}, Vector3{0, 0, 1}, Vector3{0, 0, -1}, normalize(Vector3{1, 2, -3})}) {
        const AxisFrame f = axis_frame(axis);
        const Vector3 x_cross_axis = cross(f.x, f.axis);
        EXPECT_NEAR(length(x_cross_axis - f.z), 0, 1e-6f);
        EXPECT_NEAR(dot(f.x, f.axis), 0, 1e-6f);
    }
    // The angle runs from x towards -z: a quarter turn at -z.
    EXPECT_NEAR(angle_around(y, {0, 0, -1}), 0.25f, 1e-6f);
    EXPECT_NEAR(angle_around(y, {-1, 0, 0}), 0.5f, 1e-6f);
    // Just short of a full turn rounds to 1 in float; it wraps to 0 so that u stays in [0, 1).
    EXPECT_EQ(angle_around(y, {1, 0, 1e-30f}), 0);
    EXPECT_LT(angle_around(y, {1, 0, 1e-7f}), 1);
}

TEST(Disk, DescribesBadDescriptions) {
    EXPECT_EQ(describe_problem(Disk{}), "");
    EXPECT_EQ(describe_problem(Disk{{0, 0, 0}, {0, 1, 0}, -1}), "disk radius must be > 0, got -1");
    EXPECT_EQ(describe_problem(Disk{{0, 0, 0}, {0, 1, 0}, 1, 1}),
              "disk inner_radius must be in [0, radius), got 1 with radius 1");
    EXPECT_EQ(describe_problem(Disk{{0, 0, 0}, {0, 1, 0}, 1, -0.5f}),
              "disk inner_radius must be in [0, radius), got -0.5 with radius 1");
    EXPECT_EQ(describe_problem(Disk{{0, 0, 0}, {0, 0, 0}, 1}),
              "disk normal must be a finite, non-zero direction");
    EXPECT_EQ(describe_problem(Disk{{NAN, 0, 0}}), "disk center must be finite");
    EXPECT_NE(describe_problem(Disk{{0, 0, 0}, {0, 1, 0}, INFINITY}), "");
}

TEST(Disk, PropertyChecks) {
    const Normal3 n = Normal3(normalize(Vector3{0.2f, 1, -0.4f}));
    const Disk disk{{0.1f, -0.2f, 0.3f}, n, 1.3f, 0.4f};
    PropertyOptions options;
    options.convex = true;
    options.normal_matches_gradient = true;  // of the plane's function: the disk's normal
    expect_shape_properties(
        disk, [&](Point3 p) { return dot(n, p - disk.center); }, RandomRays({0, 0, 0}, 1.5f),
        options);
}

}  // namespace
}  // namespace glint
