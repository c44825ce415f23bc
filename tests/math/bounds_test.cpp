#include "glint/math/bounds.h"

#include <gtest/gtest.h>

namespace glint {
namespace {

TEST(Bounds, DefaultIsEmptyAndMergesToItsArgument) {
    const Bounds3 empty;
    EXPECT_TRUE(empty.is_empty());
    EXPECT_EQ(empty.surface_area(), 0);
    const Bounds3 b = merge(empty, Point3{1, 2, 3});
    EXPECT_EQ(b.min, (Point3{1, 2, 3}));
    EXPECT_EQ(b.max, (Point3{1, 2, 3}));
}

TEST(Bounds, SurfaceAreaOfABox) {
    const auto b = Bounds3::of({0, 0, 0}, {1, 2, 3});
    EXPECT_FLOAT_EQ(b.surface_area(), 2 * (2 + 6 + 3));
    EXPECT_EQ(b.center(), (Point3{0.5f, 1, 1.5f}));
}

TEST(Bounds, SlabsClipTheRayToTheBox) {
    const auto b = Bounds3::of({-1, -1, -1}, {1, 1, 1});
    const auto hit = intersect_slabs(b, {{-5, 0, 0}, {1, 0, 0}}, {});
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit->min, 4);
    EXPECT_FLOAT_EQ(hit->max, 6);
    EXPECT_FALSE(intersect_slabs(b, {{-5, 2, 0}, {1, 0, 0}}, {}));
    EXPECT_FALSE(intersect_slabs(b, {{-5, 0, 0}, {-1, 0, 0}}, {}));
    EXPECT_FALSE(intersect_slabs(b, {{-5, 0, 0}, {1, 0, 0}}, {0, 3}));
}

TEST(Bounds, SlabsFromInsideStartAtTheOrigin) {
    const auto b = Bounds3::of({-1, -1, -1}, {1, 1, 1});
    const auto hit = intersect_slabs(b, {{0, 0, 0}, normalize(Vector3{1, 1, 0})}, {});
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit->min, 0);
    EXPECT_NEAR(hit->max, 1.41421356f, 1e-6);
}

}  // namespace
}  // namespace glint
