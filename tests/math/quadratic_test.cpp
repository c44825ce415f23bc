#include "glint/math/quadratic.h"

#include <gtest/gtest.h>

namespace glint {
namespace {

TEST(Quadratic, TwoRealRootsInOrder) {
    // (t - 2)(t + 3) = t^2 + t - 6
    const auto r = solve_quadratic(1, 1, -6);
    ASSERT_TRUE(r);
    EXPECT_FLOAT_EQ(r->t0, -3);
    EXPECT_FLOAT_EQ(r->t1, 2);
}

TEST(Quadratic, NegativeDiscriminantHasNoRoots) { EXPECT_FALSE(solve_quadratic(1, 0, 1)); }

TEST(Quadratic, DoubleRoot) {
    const auto r = solve_quadratic(1, -4, 4);
    ASSERT_TRUE(r);
    EXPECT_FLOAT_EQ(r->t0, 2);
    EXPECT_FLOAT_EQ(r->t1, 2);
}

TEST(Quadratic, SmallRootSurvivesCancellation) {
    // t^2 - 1e6 t + 1 = 0: roots near 1e6 and 1e-6. The textbook formula loses the small root
    // entirely in float; the stable form keeps it to full precision.
    const auto r = solve_quadratic(1, -1e6f, 1);
    ASSERT_TRUE(r);
    EXPECT_NEAR(r->t0, 1e-6, 1e-12);
    EXPECT_NEAR(r->t1, 1e6, 1);
}

TEST(Quadratic, LinearAndDegenerateEquations) {
    const auto r = solve_quadratic(0, 2, -4);
    ASSERT_TRUE(r);
    EXPECT_FLOAT_EQ(r->t0, 2);
    EXPECT_FALSE(solve_quadratic(0, 0, 1));
    const auto zero = solve_quadratic(1, 0, 0);
    ASSERT_TRUE(zero);
    EXPECT_EQ(zero->t0, 0);
    EXPECT_EQ(zero->t1, 0);
}

}  // namespace
}  // namespace glint
