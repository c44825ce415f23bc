// point_inside(): the parity of crossings on solids, and no answer for surfaces without an inside.
#include "glint/geometry/point_inside.h"

#include <gtest/gtest.h>

#include <memory>

namespace glint {
namespace {

TEST(PointInside, SphereCentreIsInsideAndAPointBesideItIsNot) {
    const Shape sphere = Sphere{{1, 2, 3}, 2};
    EXPECT_EQ(point_inside(sphere, {1, 2, 3}), true);
    EXPECT_EQ(point_inside(sphere, {2.9f, 2, 3}), true);
    // Inside the bounding box's corner, outside the sphere: the parity decides, not the box.
    EXPECT_EQ(point_inside(sphere, {2.8f, 3.8f, 3}), false);
    EXPECT_EQ(point_inside(sphere, {10, 2, 3}), false);
}

TEST(PointInside, BoxFromItsCornersToItsCentre) {
    const Shape box = Box{{0, 0, 0}, {2, 1, 4}};
    EXPECT_EQ(point_inside(box, {1, 0.5f, 2}), true);
    EXPECT_EQ(point_inside(box, {0.01f, 0.01f, 3.99f}), true);
    EXPECT_EQ(point_inside(box, {1, 1.5f, 2}), false);
}

// The docs' cube with a spherical hollow: the centre lies in the hollow, outside the solid.
TEST(PointInside, CsgDifferenceLeavesItsHollowOutside) {
    const Shape hollow =
        Csg{CsgOperation::difference, std::make_shared<const Shape>(Box{{-1, -1, -1}, {1, 1, 1}}),
            std::make_shared<const Shape>(Sphere{{0, 0, 0}, 0.8f})};
    EXPECT_EQ(point_inside(hollow, {0, 0, 0}), false);
    EXPECT_EQ(point_inside(hollow, {0.95f, 0.95f, 0.95f}), true);  // a corner of the cube
    EXPECT_EQ(point_inside(hollow, {2, 0, 0}), false);
}

TEST(PointInside, TransformedSphereIsInsideWhereItWasPlaced) {
    Transform move = Transform::translate({5, 0, 0});
    const Shape placed = Transformed(move, std::make_shared<const Shape>(Sphere{{0, 0, 0}, 1}));
    EXPECT_EQ(point_inside(placed, {5, 0, 0}), true);
    EXPECT_EQ(point_inside(placed, {0, 0, 0}), false);
}

TEST(PointInside, SurfacesWithoutAnInsideGiveNoAnswer) {
    EXPECT_EQ(point_inside(Plane{{0, 0, 0}, {0, 1, 0}}, {0, -1, 0}), std::nullopt);
    EXPECT_EQ(point_inside(Triangle{{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}}}, {0.2f, 0.2f, 0}),
              std::nullopt);
}

}  // namespace
}  // namespace glint
