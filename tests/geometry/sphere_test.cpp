#include "glint/geometry/sphere.h"

#include <gtest/gtest.h>

namespace glint {
namespace {

// The worked example of the German lecture notes ("Strahl-Kugel Schnitt, Beispiel"):
// P0 = (1 -2 -1), R || (1 2 4), M = (3 0 5), r = 3 gives t1 = 3.744, S1 = (1.816 -0.368 2.269),
// N1 = (-0.395 -0.123 -0.910). The slide rounds to three digits, hence the 2e-3 tolerance.
TEST(Sphere, WorkedExampleFromTheLectureNotes) {
    const Sphere sphere{{3, 0, 5}, 3};
    const Ray ray{{1, -2, -1}, normalize(Vector3{1, 2, 4})};
    const auto hit = sphere.intersect(ray, {});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 3.744, 2e-3);
    const SurfacePoint sp = sphere.surface_at(ray, *hit);
    EXPECT_NEAR(sp.p.x, 1.816, 2e-3);
    EXPECT_NEAR(sp.p.y, -0.368, 2e-3);
    EXPECT_NEAR(sp.p.z, 2.269, 2e-3);
    EXPECT_NEAR(sp.normal.x, -0.395, 2e-3);
    EXPECT_NEAR(sp.normal.y, -0.123, 2e-3);
    EXPECT_NEAR(sp.normal.z, -0.910, 2e-3);
    // The far intersection t2 = h + s = 6.546 + 2.802.
    const auto far = sphere.intersect(ray, {hit->t + 1e-3f, kInfinity});
    ASSERT_TRUE(far);
    EXPECT_NEAR(far->t, 9.348, 2e-3);
}

TEST(Sphere, EarlyExitWhenTheRayPointsAway) {
    const Sphere sphere{{0, 0, 5}, 1};
    EXPECT_FALSE(sphere.intersect({{0, 0, 0}, {0, 0, -1}}, {}));
}

TEST(Sphere, RayPassingByMisses) {
    const Sphere sphere{{0, 0, 5}, 1};
    EXPECT_FALSE(sphere.intersect({{0, 1.01f, 0}, {0, 0, 1}}, {}));
    EXPECT_TRUE(sphere.intersect({{0, 0.99f, 0}, {0, 0, 1}}, {}));
}

TEST(Sphere, RayFromInsideHitsTheFarSide) {
    const Sphere sphere{{0, 0, 0}, 2};
    const Ray ray{{0, 0, 0}, {1, 0, 0}};
    const auto hit = sphere.intersect(ray, {});
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit->t, 2);
    EXPECT_EQ(sphere.surface_at(ray, *hit).normal, (Normal3{1, 0, 0}));  // outward
}

TEST(Sphere, HitOutsideTheIntervalIsIgnored) {
    const Sphere sphere{{0, 0, 5}, 1};
    EXPECT_FALSE(sphere.intersect({{0, 0, 0}, {0, 0, 1}}, {0, 3.9f}));
    const auto hit = sphere.intersect({{0, 0, 0}, {0, 0, 1}}, {4.5f, kInfinity});
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit->t, 6);
}

TEST(Sphere, UvRunsAroundTheEquatorAndFromPoleToPole) {
    const Sphere sphere{{0, 0, 0}, 1};
    const auto uv_at = [&](Vector3 outward) {
        const Ray ray{to_point(outward * 3), -outward};
        return sphere.surface_at(ray, *sphere.intersect(ray, {})).uv;
    };
    EXPECT_NEAR(uv_at({1, 0, 0}).x, 0, 1e-6);
    EXPECT_NEAR(uv_at({1, 0, 0}).y, 0.5, 1e-6);
    EXPECT_NEAR(uv_at({0, 0, -1}).x, 0.25, 1e-6);  // counter-clockwise seen from above
    EXPECT_NEAR(uv_at({-1, 0, 0}).x, 0.5, 1e-6);
    EXPECT_NEAR(uv_at({0, 1, 0}).y, 1, 1e-6);
    EXPECT_NEAR(uv_at({0, -1, 0}).y, 0, 1e-6);
}

TEST(Sphere, SkippingUvChangesNothingElse) {
    const Sphere sphere{{1, 2, 3}, 2};
    const Ray ray{{4, 5, -6}, normalize(Vector3{-0.3f, -0.2f, 1})};
    const auto hit = sphere.intersect(ray, {});
    ASSERT_TRUE(hit);
    const SurfacePoint with = sphere.surface_at(ray, *hit, Uv::compute);
    const SurfacePoint without = sphere.surface_at(ray, *hit, Uv::skip);
    EXPECT_EQ(without.p, with.p);
    EXPECT_EQ(without.normal, with.normal);
    EXPECT_EQ(without.shading_normal, with.shading_normal);
    EXPECT_NE(with.uv, (Point2{0, 0}));
    EXPECT_EQ(without.uv, (Point2{0, 0}));
}

TEST(Sphere, BoundsEncloseTheSphere) {
    const Bounds3 b = Sphere{{1, 2, 3}, 0.5f}.bounds();
    EXPECT_EQ(b.min, (Point3{0.5f, 1.5f, 2.5f}));
    EXPECT_EQ(b.max, (Point3{1.5f, 2.5f, 3.5f}));
}

}  // namespace
}  // namespace glint
