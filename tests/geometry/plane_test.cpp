#include "glint/geometry/plane.h"

#include <gtest/gtest.h>

namespace glint {
namespace {

// N.P = -D with N = (0 1 0), D = -2 (the plane y = 2): t = -(D + N.P0) / (N.R).
TEST(Plane, WorkedExample) {
    const Plane plane{{0, 2, 0}, {0, 1, 0}};
    const Ray ray{{1, 0, 0}, normalize(Vector3{0, 1, 1})};
    const auto hit = plane.intersect(ray, {});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 2 * 1.41421356f, 1e-5);  // (2 - 0) / (1 / sqrt 2)
    const SurfacePoint sp = plane.surface_at(ray, *hit);
    EXPECT_NEAR(sp.p.y, 2, 1e-6);
    EXPECT_NEAR(sp.p.z, 2, 1e-5);
    EXPECT_EQ(sp.normal, (Normal3{0, 1, 0}));
}

TEST(Plane, ParallelRayMisses) {
    const Plane plane{{0, 0, 0}, {0, 1, 0}};
    EXPECT_FALSE(plane.intersect({{0, 1, 0}, {1, 0, 0}}, {}));
}

TEST(Plane, PlaneBehindTheOriginIsNotHit) {
    const Plane plane{{0, 0, 0}, {0, 1, 0}};
    EXPECT_FALSE(plane.intersect({{0, 1, 0}, {0, 1, 0}}, {}));
}

TEST(Plane, HitFromBelowKeepsTheDescribedNormal) {
    const Plane plane{{0, 0, 0}, {0, 1, 0}};
    const Ray ray{{0, -1, 0}, {0, 1, 0}};
    const auto hit = plane.intersect(ray, {});
    ASSERT_TRUE(hit);
    EXPECT_EQ(plane.surface_at(ray, *hit).normal, (Normal3{0, 1, 0}));
}

TEST(Plane, UvIsTheInPlanePositionInSceneUnits) {
    const Plane plane{{0, 0, 0}, {0, 1, 0}};
    const auto uv_of = [&](float x, float z) {
        const Ray ray{{x, 1, z}, {0, -1, 0}};
        return plane.surface_at(ray, *plane.intersect(ray, {})).uv;
    };
    const Point2 a = uv_of(0, 0), b = uv_of(3, 4);
    EXPECT_NEAR(std::hypot(b.x - a.x, b.y - a.y), 5, 1e-5);
}

}  // namespace
}  // namespace glint
