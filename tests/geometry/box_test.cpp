#include "glint/geometry/box.h"

#include <gtest/gtest.h>

namespace glint {
namespace {

const Box kBox{{-1, 0, 2}, {1, 2, 4}};

TEST(Box, SlabsGiveTheEntryFaceAndItsNormal) {
    const Ray ray{{0, 1, 0}, {0, 0, 1}};
    const auto hit = kBox.intersect(ray, {});
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit->t, 2);
    const SurfacePoint sp = kBox.surface_at(ray, *hit);
    EXPECT_EQ(sp.normal, (Normal3{0, 0, -1}));
    EXPECT_EQ(sp.p, (Point3{0, 1, 2}));
    EXPECT_FLOAT_EQ(sp.uv.x, 0.5f);  // across x
    EXPECT_FLOAT_EQ(sp.uv.y, 0.5f);  // across y
}

TEST(Box, DiagonalRayEntersThroughTheLastSlab) {
    // Enters the x slab at t = 1 and the z slab at t = 2: the box at t = 2 on the z = 2 face.
    const Ray ray{{-2, 1, 0}, normalize(Vector3{1, 0, 1})};
    const auto hit = kBox.intersect(ray, {});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 2 * 1.41421356f, 1e-5);
    EXPECT_EQ(kBox.surface_at(ray, *hit).normal, (Normal3{0, 0, -1}));
}

TEST(Box, RayFromInsideHitsTheExitFace) {
    const Ray ray{{0, 1, 3}, {0, 1, 0}};
    const auto hit = kBox.intersect(ray, {});
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit->t, 1);
    EXPECT_EQ(kBox.surface_at(ray, *hit).normal, (Normal3{0, 1, 0}));
}

TEST(Box, MissesBesideAndBehind) {
    EXPECT_FALSE(kBox.intersect({{0, 3, 0}, {0, 0, 1}}, {}));
    EXPECT_FALSE(kBox.intersect({{0, 1, 0}, {0, 0, -1}}, {}));
}

TEST(Box, AxisParallelRayOnAFacePlaneDoesNotProduceNaN) {
    // The origin lies in the plane x = -1 and the ray runs along it: 0 * inf = NaN appears in
    // the x slab, which is then ignored; the ray grazes the face and meets the box at z = 2.
    const auto hit = kBox.intersect({{-1, 1, 0}, {0, 0, 1}}, {});
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit->t, 2);
}

}  // namespace
}  // namespace glint
