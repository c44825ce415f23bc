#include "glint/geometry/triangle.h"

#include <gtest/gtest.h>

namespace glint {
namespace {

const Triangle kTriangle{{Point3{0, 0, 0}, Point3{2, 0, 0}, Point3{0, 2, 0}}};

TEST(Triangle, WorkedBarycentricHit) {
    // O + tD = b0 P0 + b1 P1 + b2 P2 at (0.5, 0.5, 0): b1 = 0.25, b2 = 0.25, t = 3.
    const Ray ray{{0.5f, 0.5f, 3}, {0, 0, -1}};
    const auto hit = kTriangle.intersect(ray, {});
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit->t, 3);
    EXPECT_FLOAT_EQ(hit->u, 0.25f);
    EXPECT_FLOAT_EQ(hit->v, 0.25f);
    const SurfacePoint sp = kTriangle.surface_at(ray, *hit);
    EXPECT_EQ(sp.p, (Point3{0.5f, 0.5f, 0}));
    EXPECT_EQ(sp.normal, (Normal3{0, 0, 1}));  // counter-clockwise seen from +z
    EXPECT_FLOAT_EQ(sp.uv.x, 0.25f);
    EXPECT_FLOAT_EQ(sp.uv.y, 0.25f);
}

TEST(Triangle, BothSidesAreHit) {
    EXPECT_TRUE(kTriangle.intersect({{0.5f, 0.5f, -3}, {0, 0, 1}}, {}));
}

TEST(Triangle, RaysOutsideTheEdgesMiss) {
    EXPECT_FALSE(kTriangle.intersect({{1.1f, 1.1f, 1}, {0, 0, -1}}, {}));  // beyond the hypotenuse
    EXPECT_FALSE(kTriangle.intersect({{-0.1f, 0.5f, 1}, {0, 0, -1}}, {}));
    EXPECT_FALSE(kTriangle.intersect({{0.5f, -0.1f, 1}, {0, 0, -1}}, {}));
}

TEST(Triangle, ParallelRayMisses) {
    EXPECT_FALSE(kTriangle.intersect({{0.5f, 0.5f, 0}, {1, 0, 0}}, {}));
}

TEST(Triangle, VertexUvsAreInterpolated) {
    Triangle t = kTriangle;
    t.uvs = {Point2{0.5f, 0.5f}, Point2{1, 0.5f}, Point2{0.5f, 1}};
    const Ray ray{{0, 2, 1}, {0, 0, -1}};  // exactly at vertex 2
    const auto hit = t.intersect(ray, {});
    ASSERT_TRUE(hit);
    const Point2 uv = t.surface_at(ray, *hit).uv;
    EXPECT_FLOAT_EQ(uv.x, 0.5f);
    EXPECT_FLOAT_EQ(uv.y, 1);
}

TEST(Triangle, CollinearVerticesHaveZeroAreaAndAreNeverHit) {
    const Triangle flat{{Point3{0, 0, 0}, Point3{1, 1, 1}, Point3{2, 2, 2}}};
    EXPECT_EQ(double_area(flat), 0);
    EXPECT_FALSE(flat.intersect({{1, 1, 0}, {0, 0, 1}}, {}));
    EXPECT_FLOAT_EQ(double_area(kTriangle), 4);
}

}  // namespace
}  // namespace glint
