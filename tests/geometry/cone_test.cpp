#include "glint/geometry/cone.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "shape_property_checks.h"

namespace glint {
namespace {

using testing::expect_shape_properties;
using testing::PropertyOptions;
using testing::RandomRays;

// Pointed: radius 1 at the base (0 0 0), 0 at the apex (0 1 0); the side has slope 45 degrees.
const Cone kPointed{{0, 0, 0}, 1, {0, 1, 0}, 0};
const Cone kPointedCapped{{0, 0, 0}, 1, {0, 1, 0}, 0, true};
// Truncated: radius 1 at y = 0, 0.5 at y = 1.
const Cone kFrustum{{0, 0, 0}, 1, {0, 1, 0}, 0.5f};
const Cone kFrustumCapped{{0, 0, 0}, 1, {0, 1, 0}, 0.5f, true};

void expect_normal(Normal3 n, Vector3 expected) {
    const Vector3 e = normalize(expected);
    EXPECT_NEAR(n.x, e.x, 1e-6f);
    EXPECT_NEAR(n.y, e.y, 1e-6f);
    EXPECT_NEAR(n.z, e.z, 1e-6f);
}

TEST(Cone, WorkedSideHitOnThePointedCone) {
    // At height 0.5 the radius is 0.5: along x the ray hits x = -0.5 at t = 4.5. The side's
    // normal leans towards the apex by the slope: (-1 1 0) / sqrt 2.
    const Ray ray{{-5, 0.5f, 0}, {1, 0, 0}};
    const auto hit = kPointed.intersect(ray, {});
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit->t, 4.5f);
    EXPECT_EQ(hit->part, 0u);
    const SurfacePoint sp = kPointed.surface_at(ray, *hit);
    EXPECT_NEAR(distance(sp.p, {-0.5f, 0.5f, 0}), 0, 1e-6f);
    expect_normal(sp.normal, {-1, 1, 0});
    EXPECT_EQ(sp.shading_normal, sp.normal);
    EXPECT_NEAR(sp.uv.x, 0.5f, 1e-6f);
    EXPECT_NEAR(sp.uv.y, 0.5f, 1e-6f);
}

TEST(Cone, SideNormalFollowsTheSlope) {
    // Radius 2 at the base, pointed at height 1: the radius falls by 2 per unit of height, so
    // the gradient of rho^2 - (2 - 2y)^2 is proportional to (-1 2 0) at (-1 0.5 0).
    const Cone steep{{0, 0, 0}, 2, {0, 1, 0}, 0};
    const Ray ray{{-5, 0.5f, 0}, {1, 0, 0}};
    const auto hit = steep.intersect(ray, {});
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit->t, 4);
    expect_normal(steep.surface_at(ray, *hit).normal, {-1, 2, 0});
    // The frustum widening upwards (radius 0.5 at the base, 1 at the top) leans the other way:
    // at height 0.5 the radius is 0.75 and the normal (-1 -0.5 0) / |.|.
    const Cone widening{{0, 0, 0}, 0.5f, {0, 1, 0}, 1};
    const auto w = widening.intersect(ray, {});
    ASSERT_TRUE(w);
    EXPECT_FLOAT_EQ(w->t, 4.25f);
    expect_normal(widening.surface_at(ray, *w).normal, {-1, -0.5f, 0});
}

TEST(Cone, TruncatedConeSideAndCaps) {
    // At height 0.5 the radius is 0.75: x = -0.75 at t = 4.25, normal (-1 0.5 0) / |.|.
    const Ray across{{-5, 0.5f, 0}, {1, 0, 0}};
    const auto side = kFrustum.intersect(across, {});
    ASSERT_TRUE(side);
    EXPECT_FLOAT_EQ(side->t, 4.25f);
    expect_normal(kFrustum.surface_at(across, *side).normal, {-1, 0.5f, 0});
    // Down the axis: through the open frustum, onto the small cap (y = 1) when capped.
    const Ray down{{0.2f, 5, 0}, {0, -1, 0}};
    EXPECT_FALSE(kFrustum.intersect(down, {}));
    const auto cap = kFrustumCapped.intersect(down, {});
    ASSERT_TRUE(cap);
    EXPECT_FLOAT_EQ(cap->t, 4);
    EXPECT_EQ(cap->part, 2u);
    const SurfacePoint sp = kFrustumCapped.surface_at(down, *cap);
    EXPECT_EQ(sp.normal, (Normal3{0, 1, 0}));
    EXPECT_NEAR(sp.uv.y, 0.4f, 1e-6f);  // 0.2 of the cap radius 0.5
    const auto base = kFrustumCapped.intersect(down, {4.5f, kInfinity});
    ASSERT_TRUE(base);
    EXPECT_FLOAT_EQ(base->t, 5);
    EXPECT_EQ(base->part, 1u);
    EXPECT_EQ(kFrustumCapped.surface_at(down, *base).normal, (Normal3{0, -1, 0}));
    // Beside the small cap but inside the base: the side is hit, not the cap.
    const Ray beside{{0.7f, 5, 0}, {0, -1, 0}};
    const auto s = kFrustumCapped.intersect(beside, {});
    ASSERT_TRUE(s);
    EXPECT_EQ(s->part, 0u);
    EXPECT_NEAR(s->t, 5 - 0.6f, 1e-6f);  // radius 0.7 at y = 0.6
}

TEST(Cone, PointedConeHasOnlyItsBaseCap) {
    // Up the axis from below: the base cap at t = 5, normal (0 -1 0).
    const Ray up{{0, -5, 0}, {0, 1, 0}};
    EXPECT_FALSE(kPointed.intersect({{0.3f, -5, 0.1f}, {0, 1, 0}}, {0, 5.5f}));
    const auto hit = kPointedCapped.intersect(up, {});
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit->t, 5);
    EXPECT_EQ(hit->part, 1u);
    EXPECT_EQ(kPointedCapped.surface_at(up, *hit).normal, (Normal3{0, -1, 0}));
    // Down onto the apex: the ray touches the point (a double root) or passes it and leaves by
    // the base cap; either way a point of the cone, with a unit normal.
    const Ray down{{0, 5, 0}, {0, -1, 0}};
    const auto apex = kPointedCapped.intersect(down, {});
    ASSERT_TRUE(apex);
    EXPECT_GE(apex->t, 4 - 1e-5f);
    EXPECT_LE(apex->t, 5 + 1e-5f);
    const SurfacePoint sp = kPointedCapped.surface_at(down, *apex);
    EXPECT_NEAR(length(to_vector(sp.normal)), 1, 1e-6f);
    EXPECT_NEAR(sp.p.x, 0, 1e-6f);
}

TEST(Cone, RayParallelToTheSide) {
    // Along (1 -1 0)/sqrt 2, parallel to the right-hand generator: the quadratic's t^2 term
    // vanishes. From (-2 1.5 0) the ray meets the left side at (-0.75 0.25 0), s = 1.25 sqrt 2,
    // and leaves by the base at (-0.5 0 0), s = 1.5 sqrt 2.
    const Ray ray{{-2, 1.5f, 0}, normalize(Vector3{1, -1, 0})};
    const auto hit = kPointed.intersect(ray, {});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 1.25f * std::sqrt(2.0f), 1e-5f);
    const SurfacePoint sp = kPointed.surface_at(ray, *hit);
    EXPECT_NEAR(distance(sp.p, {-0.75f, 0.25f, 0}), 0, 1e-5f);
    expect_normal(sp.normal, {-1, 1, 0});
    EXPECT_FALSE(kPointed.intersect(ray, {hit->t + 1e-3f, kInfinity}));
    const auto base = kPointedCapped.intersect(ray, {hit->t + 1e-3f, kInfinity});
    ASSERT_TRUE(base);
    EXPECT_NEAR(base->t, 1.5f * std::sqrt(2.0f), 1e-5f);
    EXPECT_EQ(base->part, 1u);
}

TEST(Cone, TheMirroredNappeBeyondTheApexIsCutOff) {
    // Above the apex the double cone's other half would be at radius 0.5 for y = 1.5.
    EXPECT_FALSE(kPointed.intersect({{-5, 1.5f, 0}, {1, 0, 0}}, {}));
    EXPECT_FALSE(kPointed.intersect({{-5, -0.5f, 0}, {1, 0, 0}}, {}));
}

TEST(Cone, TiltedConeMatchesTheAxisAlignedOneRotated) {
    // The pointed cone turned so its axis runs along +x: the worked hit, rotated.
    const Cone turned{{0, 0, 0}, 1, {1, 0, 0}, 0};
    const Ray ray{{0.5f, 5, 0}, {0, -1, 0}};
    const auto hit = turned.intersect(ray, {});
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit->t, 4.5f);
    expect_normal(turned.surface_at(ray, *hit).normal, {1, 1, 0});
}

TEST(Cone, FarRaysStayAccurate) {
    const Ray ray{{-1e4f, 0.5f, 0}, {1, 0, 0}};
    const auto hit = kFrustumCapped.intersect(ray, {});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 1e4 - 0.75, 1e-3);
    EXPECT_NEAR(kFrustumCapped.surface_at(ray, *hit).p.x, -0.75f, 1e-3f);
}

TEST(Cone, BoundsHoldBothEnds) {
    const Bounds3 b = kFrustum.bounds();
    EXPECT_NEAR(b.min.x, -1, 1e-5f);
    EXPECT_NEAR(b.max.z, 1, 1e-5f);
    EXPECT_EQ(b.min.y, 0);
    EXPECT_EQ(b.max.y, 1);
    const Bounds3 p = Cone{{0, 0, 0}, 0, {0, 0, 2}, 1}.bounds();  // pointed at the base
    EXPECT_NEAR(p.max.x, 1, 1e-5f);
    EXPECT_EQ(p.min.z, 0);
    EXPECT_EQ(p.max.z, 2);
}

TEST(Cone, DescribesBadDescriptions) {
    EXPECT_EQ(describe_problem(kPointed), "");
    EXPECT_EQ(describe_problem(kFrustumCapped), "");
    EXPECT_EQ(describe_problem(Cone{{0, 0, 0}, -1, {0, 1, 0}, 0}),
              "cone base_radius must be >= 0, got -1");
    EXPECT_EQ(describe_problem(Cone{{0, 0, 0}, 1, {0, 1, 0}, -2}),
              "cone apex_radius must be >= 0, got -2");
    EXPECT_EQ(describe_problem(Cone{{0, 0, 0}, 0, {0, 1, 0}, 0}),
              "cone base_radius and apex_radius must not both be 0");
    EXPECT_EQ(describe_problem(Cone{{0, 1, 0}, 1, {0, 1, 0}, 0}),
              "cone apex must differ from its base");
    EXPECT_EQ(describe_problem(Cone{{0, NAN, 0}, 1, {0, 1, 0}, 0}),
              "cone base and apex must be finite");
    EXPECT_NE(describe_problem(Cone{{0, 0, 0}, INFINITY, {0, 1, 0}, 0}), "");
}

// The cone as a signed function in its own frame (rho from the axis, y along it, h its length):
// zero on the surface, negative inside, growing outwards with unit gradient across each face.
// The side is the distance from the line through its generating segment, (rho - r(y)) / sqrt(1 +
// k^2) for the radius r(y) = base_radius + k y; the caps add the end planes, with a kink at the
// rims.
float signed_cone(const Cone& c, Point3 p) {
    const Vector3 axis = normalize(c.apex - c.base);
    const float h = length(c.apex - c.base);
    const float y = dot(p - c.base, axis);
    const float rho = length((p - c.base) - axis * y);
    const float k = (c.apex_radius - c.base_radius) / h;
    float d = (rho - (c.base_radius + k * y)) / std::sqrt(1 + k * k);
    if (c.capped) {
        if (c.base_radius > 0) d = std::max(d, -y);
        if (c.apex_radius > 0) d = std::max(d, y - h);
    }
    return d;
}

// The normal is the gradient of the side or cap it lies on; hits within the difference step of a
// rim (or of a pointed apex) see both.
PropertyOptions with_gradient(PropertyOptions options) {
    options.normal_matches_gradient = true;
    options.gradient_mismatch_fraction = 0.02f;
    return options;
}

TEST(Cone, PropertyChecksCappedConesAreConvex) {
    PropertyOptions options;
    options.convex = true;
    for (const Cone& c : {Cone{{0.1f, -0.9f, 0.2f}, 1.1f, {-0.2f, 1, -0.1f}, 0, true},
                          Cone{{0.1f, -0.9f, 0.2f}, 0.4f, {-0.2f, 1, -0.1f}, 1.0f, true}}) {
        expect_shape_properties(
            c, [&](Point3 p) { return signed_cone(c, p); }, RandomRays({0, 0, 0}, 1.5f),
            with_gradient(options));
    }
}

TEST(Cone, PropertyChecksOpenCones) {
    for (const Cone& c : {Cone{{0.1f, -0.9f, 0.2f}, 1.1f, {-0.2f, 1, -0.1f}, 0},
                          Cone{{0.1f, -0.9f, 0.2f}, 0.4f, {-0.2f, 1, -0.1f}, 1.0f}}) {
        expect_shape_properties(
            c, [&](Point3 p) { return signed_cone(c, p); }, RandomRays({0, 0, 0}, 1.5f, 99),
            with_gradient({}));
    }
}

}  // namespace
}  // namespace glint
