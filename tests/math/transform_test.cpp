#include "glint/math/transform.h"

#include <gtest/gtest.h>

#include <random>

namespace glint {
namespace {

void expect_near(Point3 a, Point3 b, float tol = 1e-5f) {
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
    EXPECT_NEAR(a.z, b.z, tol);
}

TEST(Transform, TranslateScaleRotateMovePointsAsExpected) {
    expect_near(Transform::translate({1, 2, 3})(Point3{1, 1, 1}), {2, 3, 4});
    expect_near(Transform::scale(2, 3, 4)(Point3{1, 1, 1}), {2, 3, 4});
    // A right-handed quarter turn about +z takes +x to +y.
    expect_near(Transform::rotate({0, 0, 1}, 90)(Point3{1, 0, 0}), {0, 1, 0});
    // Vectors ignore translation.
    EXPECT_EQ(Transform::translate({1, 2, 3})(Vector3{1, 0, 0}), (Vector3{1, 0, 0}));
}

TEST(Transform, CompositionAppliesTheRightOperandFirst) {
    const Transform t = Transform::translate({1, 0, 0}) * Transform::scale(2, 2, 2);
    expect_near(t(Point3{1, 1, 1}), {3, 2, 2});
}

TEST(Transform, NormalsStayPerpendicularUnderNonUniformScale) {
    // The plane x + y = 0 has normal (1,1,0); squash x by 4.
    const Transform t = Transform::scale(0.25f, 1, 1);
    const Vector3 tangent = t(Vector3{1, -1, 0});
    const Normal3 n = t(Normal3{1, 1, 0});
    EXPECT_NEAR(dot(n, tangent), 0, 1e-6);
}

TEST(Transform, RandomCompositionsRoundTrip) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(-3, 3);
    for (int i = 0; i < 100; ++i) {
        const Transform t = Transform::translate({u(rng), u(rng), u(rng)}) *
                            Transform::rotate({u(rng), u(rng), u(rng) + 0.01f}, u(rng) * 60) *
                            Transform::scale(u(rng) + 3.5f, u(rng) + 3.5f, u(rng) + 3.5f);
        const Point3 p{u(rng), u(rng), u(rng)};
        expect_near(t.inverse()(t(p)), p, 1e-4f);
        const auto via_matrix = Transform::from_matrix(t.matrix());
        ASSERT_TRUE(via_matrix);
        expect_near(via_matrix->inverse()(t(p)), p, 1e-4f);
    }
}

TEST(Transform, SingularMatrixHasNoInverse) {
    Matrix4 m = Matrix4::identity();
    m.m[2][2] = 0;
    EXPECT_FALSE(Transform::from_matrix(m));
}

TEST(Transform, BoundsContainAllTransformedCorners) {
    const auto b = Bounds3::of({-1, -1, -1}, {1, 1, 1});
    const Bounds3 r = Transform::rotate({0, 0, 1}, 45)(b);
    EXPECT_NEAR(r.max.x, 1.41421356f, 1e-5);
    EXPECT_NEAR(r.min.y, -1.41421356f, 1e-5);
    EXPECT_NEAR(r.max.z, 1, 1e-6);
}

TEST(Transform, AnUnboundedAxisStaysUnboundedWhereItGoes) {
    // A slab unbounded along x, [-1, 1] on y and z (an infinite cylinder's box).
    const Bounds3 slab{{-kInfinity, -1, -1}, {kInfinity, 1, 1}};
    const Bounds3 moved = (Transform::translate({5, 2, 0}) * Transform::scale(3, 2, 1))(slab);
    EXPECT_EQ(moved.min, (Point3{-kInfinity, 0, -1}));
    EXPECT_EQ(moved.max, (Point3{kInfinity, 4, 1}));
    // A quarter turn about z takes the unbounded axis to y; x is bounded, within rounding.
    const Bounds3 turned = Transform::rotate({0, 0, 1}, 90)(slab);
    EXPECT_EQ(turned.min.y, -kInfinity);
    EXPECT_EQ(turned.max.y, kInfinity);
    EXPECT_NEAR(turned.min.x, -1, 1e-6);
    EXPECT_NEAR(turned.max.x, 1, 1e-6);
    EXPECT_NEAR(turned.max.z, 1, 1e-6);
}

}  // namespace
}  // namespace glint
