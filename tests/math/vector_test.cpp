#include "glint/math/vector.h"

#include <gtest/gtest.h>

#include <type_traits>

namespace glint {
namespace {

template <typename A, typename B>
concept Addable = requires(A a, B b) {
    a + b;
};

TEST(Vector, PointsAndVectorsCombineOnlyMeaningfully) {
    static_assert(Addable<Point3, Vector3>);
    static_assert(Addable<Vector3, Vector3>);
    static_assert(!Addable<Point3, Point3>);
    static_assert(!Addable<Normal3, Vector3>);
    static_assert(std::is_same_v<decltype(Point3{} - Point3{}), Vector3>);
}

TEST(Vector, DotAndCrossOfWorkedExample) {
    const Vector3 a{1, 2, 4}, b{2, 2, 6};
    EXPECT_FLOAT_EQ(dot(a, b), 30);
    const Vector3 c = cross(a, b);
    EXPECT_EQ(c, (Vector3{4, 2, -2}));
    EXPECT_FLOAT_EQ(dot(c, a), 0);
    EXPECT_FLOAT_EQ(dot(c, b), 0);
    EXPECT_EQ(cross(Vector3{1, 0, 0}, Vector3{0, 1, 0}), (Vector3{0, 0, 1}));  // right-handed
}

TEST(Vector, NormalizeGivesUnitLength) {
    EXPECT_NEAR(length(normalize(Vector3{1, 2, 4})), 1, 1e-6);
    EXPECT_NEAR(length(Vector3{1, 2, 4}), 4.582576, 1e-5);  // sqrt(21)
}

TEST(Vector, FaceForwardTurnsTheNormalTowardsTheVector) {
    EXPECT_EQ(face_forward(Normal3{0, 1, 0}, Vector3{0, -1, 0}), (Normal3{0, -1, 0}));
    EXPECT_EQ(face_forward(Normal3{0, 1, 0}, Vector3{1, 1, 0}), (Normal3{0, 1, 0}));
}

TEST(Vector, OrthonormalBasisIsOrthonormalAndRightHanded) {
    for (const Vector3 n : {Vector3{0, 0, 1}, Vector3{0, 0, -1}, normalize(Vector3{1, 2, 3}),
                            normalize(Vector3{-3, 0.1f, -0.2f})}) {
        Vector3 s, t;
        orthonormal_basis(n, s, t);
        EXPECT_NEAR(length(s), 1, 1e-6);
        EXPECT_NEAR(length(t), 1, 1e-6);
        EXPECT_NEAR(dot(s, t), 0, 1e-6);
        EXPECT_NEAR(dot(s, n), 0, 1e-6);
        EXPECT_NEAR(dot(cross(s, t), n), 1, 1e-6);
    }
}

}  // namespace
}  // namespace glint
