#include "glint/geometry/torus.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "glint/math/constants.h"
#include "shape_property_checks.h"

namespace glint {
namespace {

using testing::expect_shape_properties;
using testing::PropertyOptions;
using testing::RandomRays;

// R = 1, r = 0.25 around +y through the origin.
const Torus kTorus{};

// Signed distance to the torus surface: sqrt((rho - R)^2 + y^2) - r in the axis frame.
float torus_distance(const Torus& torus, Point3 p) {
    const Vector3 a = normalize(to_vector(torus.axis));
    const Vector3 offset = p - torus.center;
    const float y = dot(offset, a);
    const float rho = length(offset - a * y);
    return std::hypot(rho - torus.major_radius, y) - torus.minor_radius;
}

TEST(Torus, AxisAlignedRayThroughBothTubesHasFourExactHits) {
    // Along x in the equatorial plane: the tube is crossed at x = -1.25, -0.75, 0.75, 1.25.
    const Ray ray{{-5, 0, 0}, {1, 0, 0}};
    float t_min = 0;
    const float expected[] = {3.75f, 4.25f, 5.75f, 6.25f};
    const float expected_normal_x[] = {-1, 1, -1, 1};  // out of the tube each time
    for (int i = 0; i < 4; ++i) {
        const auto hit = kTorus.intersect(ray, {t_min, kInfinity});
        ASSERT_TRUE(hit) << i;
        EXPECT_NEAR(hit->t, expected[i], 1e-6f) << i;
        const SurfacePoint sp = kTorus.surface_at(ray, *hit);
        EXPECT_NEAR(sp.normal.x, expected_normal_x[i], 1e-6f) << i;
        EXPECT_NEAR(sp.normal.y, 0, 1e-6f) << i;
        EXPECT_EQ(sp.shading_normal, sp.normal);
        t_min = hit->t + 1e-3f;
    }
    EXPECT_FALSE(kTorus.intersect(ray, {t_min, kInfinity}));
}

TEST(Torus, VerticalRayOntoTheTubeTop) {
    // Down onto the top of the tube at x = 1: y = r = 0.25, t = 4.75, normal +y, v = 0.25.
    const Ray top{{1, 5, 0}, {0, -1, 0}};
    const auto hit = kTorus.intersect(top, {});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 4.75f, 1e-6f);
    const SurfacePoint sp = kTorus.surface_at(top, *hit);
    EXPECT_NEAR(sp.normal.y, 1, 1e-6f);
    EXPECT_NEAR(sp.uv.x, 0, 1e-6f);
    EXPECT_NEAR(sp.uv.y, 0.25f, 1e-6f);
    // At x = 1.1 the tube's height is sqrt(r^2 - 0.1^2) = sqrt(0.0525) = 0.22912878.
    const Ray off{{1.1f, 5, 0}, {0, -1, 0}};
    const auto h = kTorus.intersect(off, {});
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 5 - 0.22912878f, 1e-6f);
}

TEST(Torus, RayThroughTheHoleMisses) {
    EXPECT_FALSE(kTorus.intersect({{0, 5, 0}, {0, -1, 0}}, {}));
    EXPECT_FALSE(kTorus.intersect({{0.7f, 5, 0.2f}, {0, -1, 0}}, {}));  // rho 0.728 < 0.75
    EXPECT_FALSE(kTorus.intersect({{-5, 0.3f, 0}, {1, 0, 0}}, {}));     // above the tube
}

TEST(Torus, UvAnglesRunAroundTheAxisAndTheTube) {
    const auto uv_of = [&](Ray ray) {
        return kTorus.surface_at(ray, *kTorus.intersect(ray, {})).uv;
    };
    // The outer equator at -z: u = 0.25, v = 0.
    const Point2 a = uv_of({{0, 0, -5}, {0, 0, 1}});
    EXPECT_NEAR(a.x, 0.25f, 1e-6f);
    EXPECT_NEAR(a.y, 0, 1e-6f);
    // The inner equator seen from the hole at +x: u = 0, v = 0.5.
    const Point2 b = uv_of({{0, 0, 0}, {1, 0, 0}});
    EXPECT_NEAR(b.x, 0, 1e-6f);
    EXPECT_NEAR(b.y, 0.5f, 1e-6f);
    // The bottom of the tube at -x: u = 0.5, v = 0.75.
    const Point2 c = uv_of({{-1, -5, 0}, {0, 1, 0}});
    EXPECT_NEAR(c.x, 0.5f, 1e-6f);
    EXPECT_NEAR(c.y, 0.75f, 1e-6f);
}

TEST(Torus, GrazingRaysAlongTheTubeTop) {
    // The plane y = r touches the torus along the circle rho = R. Along x at z = 0 the torus
    // function is (x^2 - R^2)^2: double roots at x = -1 and x = 1.
    // The quartic's double root counts as a hit: the tangent point, with the normal up.
    const Ray tangent{{-5, 0.25f, 0}, {1, 0, 0}};
    const auto touch = kTorus.intersect(tangent, {});
    ASSERT_TRUE(touch);
    EXPECT_NEAR(touch->t, 4, 1e-5f);
    EXPECT_NEAR(kTorus.surface_at(tangent, *touch).normal.y, 1, 1e-6f);
    // Just below: two close roots around x = -1 with half-width sqrt(2 r delta) for
    // (x + 1)^2 ~= 2 r delta: delta = 1e-4 gives 0.00707.
    const Ray below{{-5, 0.25f - 1e-4f, 0}, {1, 0, 0}};
    const auto hit = kTorus.intersect(below, {});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 4 - 0.00707, 2e-4);
    EXPECT_NEAR(torus_distance(kTorus, below.at(hit->t)), 0, 1e-6f);
    const auto exit = kTorus.intersect(below, {hit->t + 1e-3f, kInfinity});
    ASSERT_TRUE(exit);
    EXPECT_NEAR(exit->t, 4 + 0.00707, 2e-4);
    // Just above: nothing.
    EXPECT_FALSE(kTorus.intersect({{-5, 0.25f + 1e-4f, 0}, {1, 0, 0}}, {}));
    EXPECT_FALSE(kTorus.intersect({{-5, 0.25f + 1e-6f, 0}, {1, 0, 0}}, {}));
}

TEST(Torus, GrazingRaysAlongTheTubeSide) {
    // Vertical rays at rho = R + r = 1.25 touch the outer equator, at rho = R - r = 0.75 the
    // inner one; a hair inside the tube they cross it, a hair outside they miss.
    for (const float x : {1.25f, 0.75f}) {
        const auto touch = kTorus.intersect({{x, 5, 0}, {0, -1, 0}}, {});
        ASSERT_TRUE(touch) << x;
        EXPECT_NEAR(touch->t, 5, 1e-5f) << x;
    }
    EXPECT_FALSE(kTorus.intersect({{0.75f - 1e-5f, 5, 0}, {0, -1, 0}}, {}));
    const auto hit = kTorus.intersect({{1.25f - 1e-5f, 5, 0}, {0, -1, 0}}, {});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 5, 3e-3f);  // y = +-sqrt(2 r 1e-5) = 0.00224
    EXPECT_FALSE(kTorus.intersect({{1.25f + 1e-5f, 5, 0}, {0, -1, 0}}, {}));
}

TEST(Torus, RaysFromFarAwayLandOnTheSurface) {
    // From 1e4 away along x at height 0.1: (rho - 1)^2 + 0.01 = 0.0625, so x = -1.2291288.
    const Ray ray{{-1e4f, 0.1f, 0}, {1, 0, 0}};
    const auto hit = kTorus.intersect(ray, {});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 1e4 - 1.2291288, 1e-3);  // float t has ulp 1e-3 at 1e4
    const SurfacePoint sp = kTorus.surface_at(ray, *hit);
    EXPECT_NEAR(torus_distance(kTorus, sp.p), 0, 1e-6f);
    EXPECT_NEAR(distance(sp.p, {-1.2291288f, 0.1f, 0}), 0, 1e-3f);

    // Random directions from 1e4 away, aimed at the tube: each hit agrees with the same ray
    // started close by (where float is exact enough), to float precision at 1e4.
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> unit(-1, 1);
    int hits = 0;
    for (int i = 0; i < 200; ++i) {
        const float angle = kPi * unit(rng);
        const Point3 aim{1.1f * std::cos(angle), 0.2f * unit(rng), 1.1f * std::sin(angle)};
        Vector3 from{unit(rng), unit(rng), unit(rng)};
        if (length(from) < 0.1f) continue;
        const Vector3 d = -normalize(from);
        const Ray far{aim - d * 1e4f, d};
        const auto far_hit = kTorus.intersect(far, {});
        const Ray close{aim - d * 3.0f, d};
        const auto close_hit = kTorus.intersect(close, {});
        ASSERT_EQ(bool(far_hit), bool(close_hit)) << i;
        if (!far_hit) continue;
        ++hits;
        const SurfacePoint on_surface = kTorus.surface_at(far, *far_hit);
        EXPECT_NEAR(torus_distance(kTorus, on_surface.p), 0, 1e-5f) << i;
        EXPECT_NEAR(distance(far.at(far_hit->t), close.at(close_hit->t)), 0, 2e-3f) << i;
    }
    EXPECT_GT(hits, 150);
}

TEST(Torus, TiltedAndMovedTorus) {
    // The axis along +z, centre (1 2 3): down the axis direction onto the tube top at (2 2 3.25).
    const Torus t{{1, 2, 3}, {0, 0, 1}, 1, 0.25f};
    const Ray ray{{2, 2, 10}, {0, 0, -1}};
    const auto hit = t.intersect(ray, {});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 6.75f, 1e-5f);
    EXPECT_NEAR(t.surface_at(ray, *hit).normal.z, 1, 1e-6f);
}

TEST(Torus, BoundsAreTight) {
    const Bounds3 b = kTorus.bounds();
    EXPECT_NEAR(b.min.x, -1.25f, 1e-5f);
    EXPECT_NEAR(b.max.z, 1.25f, 1e-5f);
    EXPECT_NEAR(b.min.y, -0.25f, 1e-5f);
    EXPECT_NEAR(b.max.y, 0.25f, 1e-5f);
    // Axis (1 1 0)/sqrt 2: R sqrt(1/2) + r along x and y, R + r along z.
    const Bounds3 tilted = Torus{{0, 0, 0}, Normal3(normalize(Vector3{1, 1, 0}))}.bounds();
    EXPECT_NEAR(tilted.max.x, 1 / std::sqrt(2.0f) + 0.25f, 1e-5f);
    EXPECT_NEAR(tilted.max.z, 1.25f, 1e-5f);
}

TEST(Torus, DescribesBadDescriptions) {
    EXPECT_EQ(describe_problem(kTorus), "");
    EXPECT_EQ(describe_problem(Torus{{0, 0, 0}, {0, 1, 0}, 0.5f, 1}),
              "torus major_radius must be greater than minor_radius (a ring torus), got "
              "major_radius 0.5 and minor_radius 1");
    EXPECT_EQ(describe_problem(Torus{{0, 0, 0}, {0, 1, 0}, 1, 0}),
              "torus minor_radius must be > 0, got 0");
    EXPECT_EQ(describe_problem(Torus{{0, 0, 0}, {0, 0, 0}}),
              "torus axis must be a finite, non-zero direction");
    EXPECT_EQ(describe_problem(Torus{{INFINITY, 0, 0}}), "torus center must be finite");
    EXPECT_NE(describe_problem(Torus{{0, 0, 0}, {0, 1, 0}, INFINITY, 1}), "");
}

TEST(Torus, PropertyChecks) {
    for (const Torus& t :
         {Torus{{0.1f, -0.2f, 0.05f}, Normal3(normalize(Vector3{0.3f, 1, -0.2f})), 1, 0.3f},
          Torus{{0, 0, 0}, {1, 0, 0}, 0.9f, 0.6f}}) {
        PropertyOptions options;
        options.normal_matches_gradient = true;
        expect_shape_properties(
            t, [&](Point3 p) { return torus_distance(t, p); }, RandomRays({0, 0, 0}, 1.5f),
            options);
    }
}

}  // namespace
}  // namespace glint
