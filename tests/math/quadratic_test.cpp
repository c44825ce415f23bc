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

TEST(QuadraticDouble, RootsOfDoubleCoefficientsKeepTheirPrecision) {
    // (s - 1)(s - 1.0000001) = s^2 - 2.0000001 s + 1.0000001. In float, -2.0000001 rounds to
    // -2.00000012 and the roots move by about 1e-4; in double both stay within 1e-8.
    const auto r = solve_quadratic_double(1, -2.0000001, 1.0000001);
    ASSERT_TRUE(r);
    EXPECT_NEAR(r->t0, 1.0, 1e-8);
    EXPECT_NEAR(r->t1, 1.0000001, 1e-8);
}

TEST(QuadraticDouble, SameCasesAsInFloat) {
    const auto two = solve_quadratic_double(1, 1, -6);  // (s - 2)(s + 3)
    ASSERT_TRUE(two);
    EXPECT_EQ(two->t0, -3);
    EXPECT_EQ(two->t1, 2);
    EXPECT_FALSE(solve_quadratic_double(1, 0, 1));
    // Roots 1e-6 (1 + 1e-12) and 1e6 (1 - 1e-12), to first order.
    const auto small = solve_quadratic_double(1, -1e6, 1);
    ASSERT_TRUE(small);
    EXPECT_NEAR(small->t0, 1e-6 * (1 + 1e-12), 1e-21);
    EXPECT_NEAR(small->t1, 1e6 * (1 - 1e-12), 1e-9);
    const auto linear = solve_quadratic_double(0, 2, -4);
    ASSERT_TRUE(linear);
    EXPECT_EQ(linear->t0, 2);
    EXPECT_EQ(linear->t1, 2);
    EXPECT_FALSE(solve_quadratic_double(0, 0, 1));
}

}  // namespace
}  // namespace glint
