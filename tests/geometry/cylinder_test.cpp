#include "glint/geometry/cylinder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "shape_property_checks.h"

namespace glint {
namespace {

using testing::expect_shape_properties;
using testing::PropertyOptions;
using testing::RandomRays;

// The unit cylinder along y: base (0 0 0), top (0 1 0), radius 1.
const Cylinder kOpen{{0, 0, 0}, {0, 1, 0}, 1};
const Cylinder kCapped{{0, 0, 0}, {0, 1, 0}, 1, true};

TEST(Cylinder, WorkedSideHit) {
    // Along x at height 0.5: x^2 = 1 gives x = -1 at t = 4, normal (-1 0 0).
    const Ray ray{{-5, 0.5f, 0}, {1, 0, 0}};
    const auto hit = kOpen.intersect(ray, {});
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit->t, 4);
    EXPECT_EQ(hit->part, 0u);
    const SurfacePoint sp = kOpen.surface_at(ray, *hit);
    EXPECT_NEAR(distance(sp.p, {-1, 0.5f, 0}), 0, 1e-6f);
    EXPECT_NEAR(sp.normal.x, -1, 1e-6f);
    EXPECT_NEAR(sp.normal.y, 0, 1e-6f);
    EXPECT_NEAR(sp.normal.z, 0, 1e-6f);
    EXPECT_EQ(sp.shading_normal, sp.normal);
    EXPECT_NEAR(sp.uv.x, 0.5f, 1e-6f);  // half way round from +x
    EXPECT_NEAR(sp.uv.y, 0.5f, 1e-6f);  // half way up
    // The far side at t = 6, normal (1 0 0).
    const auto far = kOpen.intersect(ray, {4.001f, kInfinity});
    ASSERT_TRUE(far);
    EXPECT_FLOAT_EQ(far->t, 6);
    EXPECT_NEAR(kOpen.surface_at(ray, *far).normal.x, 1, 1e-6f);
}

TEST(Cylinder, SideUvRunsAroundFromXTowardsMinusZ) {
    const Ray ray{{0, 0.25f, -5}, {0, 0, 1}};
    const SurfacePoint sp = kOpen.surface_at(ray, *kOpen.intersect(ray, {}));
    EXPECT_NEAR(sp.uv.x, 0.25f, 1e-6f);  // at -z
    EXPECT_NEAR(sp.uv.y, 0.25f, 1e-6f);
}

TEST(Cylinder, CapHits) {
    // Down the axis: the open tube lets the ray through; the capped one stops it on the top cap.
    const Ray down{{0, 5, 0}, {0, -1, 0}};
    EXPECT_FALSE(kOpen.intersect(down, {}));
    const auto top = kCapped.intersect(down, {});
    ASSERT_TRUE(top);
    EXPECT_FLOAT_EQ(top->t, 4);
    EXPECT_EQ(top->part, 2u);
    EXPECT_EQ(kCapped.surface_at(down, *top).normal, (Normal3{0, 1, 0}));
    // Leaving through the base cap at t = 5, normal (0 -1 0).
    const auto base = kCapped.intersect(down, {4.5f, kInfinity});
    ASSERT_TRUE(base);
    EXPECT_FLOAT_EQ(base->t, 5);
    EXPECT_EQ(base->part, 1u);
    EXPECT_EQ(kCapped.surface_at(down, *base).normal, (Normal3{0, -1, 0}));
    // Off the axis: polar uv on the cap, v = distance from the axis / radius.
    const Ray off{{0.5f, 5, 0}, {0, -1, 0}};
    const SurfacePoint sp = kCapped.surface_at(off, *kCapped.intersect(off, {}));
    EXPECT_EQ(sp.p, (Point3{0.5f, 1, 0}));
    EXPECT_NEAR(sp.uv.x, 0, 1e-6f);
    EXPECT_NEAR(sp.uv.y, 0.5f, 1e-6f);
}

TEST(Cylinder, RaysParallelToTheSide) {
    // Inside the tube, along the axis: only caps can stop it.
    const Ray inside{{0.5f, -5, 0.3f}, {0, 1, 0}};
    EXPECT_FALSE(kOpen.intersect(inside, {}));
    const auto hit = kCapped.intersect(inside, {});
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit->t, 5);
    EXPECT_EQ(hit->part, 1u);
    // Outside the tube: nothing at all.
    EXPECT_FALSE(kCapped.intersect({{1.5f, -5, 0}, {0, 1, 0}}, {}));
}

TEST(Cylinder, RaysThroughTheOpenEndHitTheInsideWithAnOutwardNormal) {
    // From (0 2.5 0) along (1 -2 0)/sqrt 5: x = 1 at s = sqrt 5, where y = 0.5.
    const Ray ray{{0, 2.5f, 0}, normalize(Vector3{1, -2, 0})};
    const auto hit = kOpen.intersect(ray, {});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, std::sqrt(5.0f), 1e-6f);
    EXPECT_NEAR(kOpen.surface_at(ray, *hit).normal.x, 1, 1e-6f);  // away from the axis
    // The capped one stops it at the top cap first: y = 1 at s = 1.5 sqrt 5 / 2.
    const auto cap = kCapped.intersect(ray, {});
    ASSERT_TRUE(cap);
    EXPECT_NEAR(cap->t, 0.75f * std::sqrt(5.0f), 1e-6f);
}

TEST(Cylinder, RayFromInsideHitsTheSideWithAnOutwardNormal) {
    const Ray ray{{0, 0.5f, 0}, {0, 0, 1}};
    const auto hit = kCapped.intersect(ray, {});
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit->t, 1);
    EXPECT_NEAR(kCapped.surface_at(ray, *hit).normal.z, 1, 1e-6f);
}

TEST(Cylinder, HitsBeyondTheEndsMiss) {
    EXPECT_FALSE(kOpen.intersect({{-5, 1.01f, 0}, {1, 0, 0}}, {}));
    EXPECT_FALSE(kOpen.intersect({{-5, -0.01f, 0}, {1, 0, 0}}, {}));
    EXPECT_FALSE(kOpen.intersect({{-5, 0.5f, 1.01f}, {1, 0, 0}}, {}));
}

TEST(Cylinder, FarRaysStayAccurate) {
    // From 1e4 away at height 0.5 and z = 0.1: x = -sqrt(1 - 0.01) = -0.994987.
    const Ray ray{{-1e4f, 0.5f, 0.1f}, {1, 0, 0}};
    const auto hit = kCapped.intersect(ray, {});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 1e4 - 0.99498744, 1e-3);  // float t has ulp 1e-3 at 1e4
    const SurfacePoint sp = kCapped.surface_at(ray, *hit);
    EXPECT_NEAR(std::hypot(sp.p.x, sp.p.z), 1, 1e-6f);
    EXPECT_NEAR(sp.p.x, -0.99498744f, 1e-3f);
}

TEST(Cylinder, RaysJustInsideTheRimFromAnyDistanceHit) {
    // The early out for rays that pass the axis farther than the radius must never reject a
    // ray that passes just inside it: from near and far, straight across and tilted.
    for (const float distance : {2.0f, 30.0f, 1e3f, 1e5f}) {
        for (const float tilt : {0.0f, 0.3f, 1.2f}) {
            for (const float inside : {1e-3f, 1e-5f}) {
                const float z = 1 - inside;
                const Vector3 d = normalize(Vector3{1, tilt, 0});
                const Point3 target{0, 0.5f, z};
                const Ray ray{target - d * distance, d};
                const auto hit = kOpen.intersect(ray, {});
                ASSERT_TRUE(hit) << distance << " " << tilt << " " << inside;
                EXPECT_NEAR(hit->t, distance - std::sqrt(1 - z * z) / d.x,
                            2e-6f * distance + 1e-3f);
                // The same ray just outside the rim misses.
                const Ray outside{ray.origin + Vector3{0, 0, 2 * inside}, d};
                if (distance < 1e3f) {
                    EXPECT_FALSE(kOpen.intersect(outside, {}));
                }
            }
        }
    }
}

TEST(Cylinder, BoundsHoldTheEndDisks) {
    const Bounds3 b = Cylinder{{1, 0, 0}, {1, 2, 0}, 0.5f}.bounds();
    EXPECT_NEAR(b.min.x, 0.5f, 1e-5f);
    EXPECT_NEAR(b.max.x, 1.5f, 1e-5f);
    EXPECT_EQ(b.min.y, 0);
    EXPECT_EQ(b.max.y, 2);
    EXPECT_NEAR(b.min.z, -0.5f, 1e-5f);
    // Along the diagonal (1 1 0)/sqrt 2: each end disk reaches 0.5 / sqrt 2 along x and y.
    const Bounds3 d = Cylinder{{0, 0, 0}, {1, 1, 0}, 0.5f}.bounds();
    EXPECT_NEAR(d.min.x, -0.5f / std::sqrt(2.0f), 1e-5f);
    EXPECT_NEAR(d.max.y, 1 + 0.5f / std::sqrt(2.0f), 1e-5f);
    EXPECT_NEAR(d.max.z, 0.5f, 1e-5f);
}

TEST(Cylinder, DescribesBadDescriptions) {
    EXPECT_EQ(describe_problem(Cylinder{{0, 0, 0}, {0, 1, 0}}), "");
    EXPECT_EQ(describe_problem(Cylinder{{0, 0, 0}, {0, 1, 0}, 0}),
              "cylinder radius must be > 0, got 0");
    EXPECT_EQ(describe_problem(Cylinder{{1, 2, 3}, {1, 2, 3}}),
              "cylinder top must differ from its base");
    EXPECT_EQ(describe_problem(Cylinder{{0, 0, 0}, {0, INFINITY, 0}}),
              "cylinder base and top must be finite");
    EXPECT_EQ(describe_problem(Cylinder{{0, -3e38f, 0}, {0, 3e38f, 0}}),
              "cylinder is too long: the distance from base to top overflows a float");
    EXPECT_NE(describe_problem(Cylinder{{0, 0, 0}, {0, 1, 0}, NAN}), "");
}

// The cylinder as a signed function in its own frame (rho from the axis, y along it): zero on the
// surface, negative inside, growing outwards with unit gradient across each face. The side is
// rho - radius; the caps add the end planes, max(side, -y, y - h), with a kink at the rims.
float signed_cylinder(const Cylinder& c, Point3 p, bool caps) {
    const Vector3 axis = normalize(c.top - c.base);
    const float h = length(c.top - c.base);
    const float y = dot(p - c.base, axis);
    const float side = length((p - c.base) - axis * y) - c.radius;
    return caps ? std::max({side, -y, y - h}) : side;
}

// The normal is the gradient of the side or cap it lies on; hits within the difference step of a
// rim see both.
PropertyOptions with_gradient(PropertyOptions options, bool caps) {
    options.normal_matches_gradient = true;
    options.gradient_mismatch_fraction = caps ? 0.02f : 0;
    return options;
}

TEST(Cylinder, PropertyChecksCappedIsConvex) {
    const Cylinder c{{0.2f, -0.9f, 0.1f}, {-0.3f, 1, 0.4f}, 0.7f, true};
    PropertyOptions options;
    options.convex = true;
    expect_shape_properties(
        c, [&](Point3 p) { return signed_cylinder(c, p, true); }, RandomRays({0, 0, 0}, 1.5f),
        with_gradient(options, true));
}

TEST(Cylinder, PropertyChecksOpen) {
    const Cylinder c{{0.2f, -0.9f, 0.1f}, {-0.3f, 1, 0.4f}, 0.7f};
    expect_shape_properties(
        c, [&](Point3 p) { return signed_cylinder(c, p, false); }, RandomRays({0, 0, 0}, 1.5f, 777),
        with_gradient({}, false));
}

}  // namespace
}  // namespace glint
