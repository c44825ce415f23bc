// The margin every structure grows its boxes by: its worked values, and its place below the offset
// of a ray leaving a surface.
#include "glint/accel/rounding_margin.h"

#include <gtest/gtest.h>

#include "glint/math/constants.h"
#include "glint/render/world.h"

namespace glint {
namespace {

TEST(RoundingMargin, IsEightUlpsOfTheLargestCoordinate) {
    // 10 * 2^-20 = 9.5367431640625e-6, whatever the extent.
    EXPECT_EQ(rounding_margin({{-10, -10, -10}, {10, 10, 10}}), 0x1.4p-17f);
    EXPECT_EQ(rounding_margin({{9, 9, 9}, {10, 10, 10}}), 0x1.4p-17f);
    // The largest magnitude may be a minimum: -5 here.
    EXPECT_EQ(rounding_margin({{2, 0, -5}, {3, 1, -4}}), 5 * 0x1p-20f);
    // A flat scene in the plane z = 0 still gets boxes of positive thickness.
    EXPECT_EQ(rounding_margin({{0, 0, 0}, {4, 2, 0}}), 4 * 0x1p-20f);
}

TEST(RoundingMargin, IsOneForAPointAtTheOriginAndForNonFiniteBounds) {
    EXPECT_EQ(rounding_margin({{0, 0, 0}, {0, 0, 0}}), 1);
    EXPECT_EQ(rounding_margin({{0, 0, 0}, {kInfinity, 1, 1}}), 1);
}

// A ray leaving the face z = 0 of a scene [-10, 10]^3 starts 10^-5 * 10 = 10^-4 off it
// (World::spawn_ray), ten margins away: outside the face's grown box, so no structure tests the
// face it leaves again.
TEST(RoundingMargin, StaysWellUnderTheOffsetOfASpawnedRay) {
    const Bounds3 scene{{-10, -10, -10}, {10, 10, 10}};
    const float offset = kRelativeRayEpsilon * magnitude(scene);
    EXPECT_FLOAT_EQ(offset, 1e-4f);
    EXPECT_GT(offset, 10 * rounding_margin(scene));
}

}  // namespace
}  // namespace glint
