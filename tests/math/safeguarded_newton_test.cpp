#include "glint/math/safeguarded_newton.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace glint {
namespace {

struct Sample {
    double value, slope;
};

// t^2 - 2 on [1, 2]: the midpoint 1.5, then pure Newton steps t <- t - (t^2 - 2) / 2t:
// 1.5 -> 1.41666667 -> 1.41421569 -> 1.41421356237469 -> 1.41421356237310 (= sqrt 2).
// Quadratic convergence: the step sizes are 0.0833, 0.00245, 2.1e-6, 1.6e-12.
TEST(SafeguardedNewton, WorkedExampleConvergesQuadratically) {
    std::vector<double> iterates;
    const auto f = [&](double t) {
        iterates.push_back(t);
        return Sample{t * t - 2, 2 * t};
    };
    const NewtonResult r = safeguarded_newton(f, 1, 2, -1, 2, 1e-12);
    EXPECT_TRUE(r.converged);
    EXPECT_DOUBLE_EQ(r.x, std::sqrt(2.0));
    const std::vector<double> expected{1.5, 1.4166666666666667, 1.4142156862745099,
                                       1.4142135623746899, 1.4142135623730951};
    ASSERT_EQ(iterates.size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i) EXPECT_NEAR(iterates[i], expected[i], 1e-15);
    EXPECT_EQ(r.evaluations, 5);
}

// atan t on [-1, 10]: from the midpoint 4.5 Newton would jump to 4.5 - atan(4.5) (1 + 4.5^2)
// = -24.3, far outside the bracket, so the method bisects: 4.5 -> 1.75 -> 0.375. There the
// Newton step stays inside and converges: -0.0342228 -> 2.67149e-5 -> -1.27e-14 -> 0.
TEST(SafeguardedNewton, BisectsWhereNewtonWouldLeaveTheBracket) {
    std::vector<double> iterates;
    const auto f = [&](double t) {
        iterates.push_back(t);
        return Sample{std::atan(t), 1 / (1 + t * t)};
    };
    const NewtonResult r = safeguarded_newton(f, -1, 10, std::atan(-1.0), std::atan(10.0), 1e-12);
    EXPECT_TRUE(r.converged);
    EXPECT_NEAR(r.x, 0, 1e-12);
    ASSERT_GE(iterates.size(), 6u);
    EXPECT_DOUBLE_EQ(iterates[0], 4.5);
    EXPECT_DOUBLE_EQ(iterates[1], 1.75);                    // bisection
    EXPECT_DOUBLE_EQ(iterates[2], 0.375);                   // bisection
    EXPECT_NEAR(iterates[3], -0.03422279577737147, 1e-15);  // Newton from here on
    EXPECT_NEAR(iterates[4], 2.671489723596321e-05, 1e-17);
    EXPECT_NEAR(iterates[5], -1.2710694991110646e-14, 1e-20);
}

TEST(SafeguardedNewton, ZeroAtAnEndIsTheRoot) {
    const auto f = [](double t) { return Sample{t - 1, 1}; };
    EXPECT_EQ(safeguarded_newton(f, 1, 3, 0, 2, 1e-9).x, 1);
    EXPECT_EQ(safeguarded_newton(f, -1, 1, -2, 0, 1e-9).x, 1);
}

TEST(SafeguardedNewton, ZeroSlopeFallsBackToBisection) {
    // t^3 has a zero slope at its root; the iterates still close in on it.
    const auto f = [](double t) { return Sample{t * t * t, 3 * t * t}; };
    const NewtonResult r = safeguarded_newton(f, -1, 2, -1, 8, 1e-10);
    EXPECT_NEAR(r.x, 0, 1e-3);
    EXPECT_LE(r.evaluations, 100);
}

TEST(SafeguardedNewton, NaNStopsWithoutConverging) {
    const auto f = [](double t) { return Sample{t > 0.25 ? std::nan("") : t - 0.5, 1}; };
    const NewtonResult r = safeguarded_newton(f, 0, 2, -0.5, 1.5, 1e-12);
    EXPECT_FALSE(r.converged);
}

TEST(SafeguardedNewton, EvaluationBudgetIsRespected) {
    int calls = 0;
    const auto f = [&](double t) {
        ++calls;
        return Sample{std::sin(50 * t) + 0.3, 50 * std::cos(50 * t)};
    };
    // A tolerance of 0 is never met: only the budget stops the iteration.
    safeguarded_newton(f, 0, 0.08, 0.3, std::sin(4.0) + 0.3, 0, 7);
    EXPECT_LE(calls, 7);
}

}  // namespace
}  // namespace glint
