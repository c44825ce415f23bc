// Tests of the chi-square helper itself: its p-values, pooling, integration and hard failures.
#include "chi_square.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "glint/sampling/random.h"

namespace glint {
namespace {

// Q(n, x) for integer n is the chance of fewer than n events of a Poisson(x) process:
// e^-x sum_{k<n} x^k / k!, an independent closed form to check the general algorithm against.
double poisson_below(int n, double x) {
    double term = std::exp(-x), sum = 0;
    for (int k = 0; k < n; ++k) {
        sum += term;
        term *= x / (k + 1);
    }
    return sum;
}

TEST(RegularizedUpperGamma, MatchesClosedForms) {
    for (double x : {0.1, 1.0, 2.5, 5.0, 30.0}) {
        EXPECT_NEAR(regularized_upper_gamma(1, x), std::exp(-x), 1e-12) << x;
        EXPECT_NEAR(regularized_upper_gamma(0.5, x), std::erfc(std::sqrt(x)), 1e-12) << x;
    }
    EXPECT_EQ(regularized_upper_gamma(3, 0), 1);
    // Large a, on both sides of the switch between series and continued fraction (x = a + 1).
    for (double x : {300.0, 380.0, 400.5, 401.5, 420.0, 500.0}) {
        EXPECT_NEAR(regularized_upper_gamma(400, x), poisson_below(400, x), 1e-10) << x;
    }
}

TEST(ChiSquarePValue, MatchesTableValues) {
    // 95th percentiles from any chi-square table.
    EXPECT_NEAR(chi_square_p_value(3.841, 1), 0.05, 1e-4);
    EXPECT_NEAR(chi_square_p_value(18.307, 10), 0.05, 1e-4);
    EXPECT_NEAR(chi_square_p_value(124.342, 100), 0.05, 1e-4);
    // Two degrees of freedom: p = e^(-statistic / 2).
    EXPECT_NEAR(chi_square_p_value(7, 2), std::exp(-3.5), 1e-12);
}

TEST(SidakSignificance, WorkedNumbers) {
    EXPECT_NEAR(sidak_significance(0.01, 1), 0.01, 1e-15);
    EXPECT_NEAR(sidak_significance(0.05, 2), 1 - std::sqrt(0.95), 1e-15);  // 0.0253206
    EXPECT_NEAR(sidak_significance(0.01, 12), 0.01 / 12, 1e-5);
}

TEST(Integration, SimpsonAndMidpointWorkedIntegrals) {
    EXPECT_NEAR(adaptive_simpson([](double x) { return std::sin(x); }, 0, std::numbers::pi, 1e-12),
                2, 1e-10);
    EXPECT_NEAR(adaptive_simpson_2d([](double x, double y) { return x * y; }, 0, 1, 0, 2, 1e-12), 1,
                1e-10);
    // The unit disk's area, with its edge crossing cells of side 0.002: the midpoint rule errs
    // only in those cells, by much less than their total area (0.025).
    const double disk = midpoint_2d(
        [](double x, double y) { return x * x + y * y < 1 ? 1.0 : 0.0; }, -1, 1, -1, 1, 1000);
    EXPECT_NEAR(disk, std::numbers::pi, 1e-3);
}

TEST(ChiSquareStatistic, HandWorkedExample) {
    // 100 samples in 4 equally likely bins, observed 30, 20, 25, 25: chi-square
    // (25 + 25 + 0 + 0) / 25 = 2 on 3 degrees of freedom, p = Q(1.5, 1) = erfc(1) +
    // 2 e^-1 / sqrt(pi) = 0.572407.
    const ChiSquareGrid grid{0, 4, 4, 0, 1, 1};
    const auto r = chi_square_statistic(grid, {30, 20, 25, 25}, {0.25, 0.25, 0.25, 0.25}, 100);
    EXPECT_NEAR(r.statistic, 2, 1e-12);
    EXPECT_EQ(r.dof, 3);
    EXPECT_NEAR(r.p_value, 0.572407, 1e-6);
}

TEST(ChiSquareStatistic, PoolsBinsExpectingFewerThanFive) {
    // Expected 2, 2, 3, 493, 500 of 1000: the first three pool into one cell expecting 7 that
    // observes 10. Chi-square 9/7 + 9/493 + 0 = 1.303970 on 2 degrees of freedom.
    const ChiSquareGrid grid{0, 5, 5, 0, 1, 1};
    const auto r =
        chi_square_statistic(grid, {5, 4, 1, 490, 500}, {0.002, 0.002, 0.003, 0.493, 0.5}, 1000);
    EXPECT_NEAR(r.statistic, 9.0 / 7 + 9.0 / 493, 1e-12);
    EXPECT_EQ(r.dof, 2);
    EXPECT_NEAR(r.p_value, std::exp(-r.statistic / 2), 1e-12);
    EXPECT_NE(r.description.find("3 bins"), std::string::npos) << r.description;
}

TEST(ChiSquareTest, AcceptsUniformAndRejectsSkewedSamples) {
    const ChiSquareGrid grid{0, 1, 50, 0, 1, 1};
    const auto uniform = bin_probabilities_simpson(grid, [](double, double) { return 1.0; });
    const auto accepted = chi_square_test(grid, uniform, 100000, [](std::uint64_t i) {
        return GridPoint{random_float(i, 0, 0, 31), 0.5};
    });
    EXPECT_GT(accepted.p_value, 0.01) << accepted.description;
    // u^1.05 is only slightly skewed towards 0 but is caught.
    const auto rejected = chi_square_test(grid, uniform, 100000, [](std::uint64_t i) {
        return GridPoint{std::pow(random_float(i, 0, 0, 31), 1.05), 0.5};
    });
    EXPECT_LT(rejected.p_value, 1e-6) << rejected.description;
}

TEST(ChiSquareTest, FailsOutrightOnImpossibleSamplesAndUnnormalisedDensities) {
    const ChiSquareGrid grid{0, 1, 10, 0, 1, 1};
    const auto uniform = bin_probabilities_simpson(grid, [](double, double) { return 1.0; });
    const auto outside = chi_square_test(grid, uniform, 1000, [](std::uint64_t i) {
        return GridPoint{i == 500 ? 1.5 : 0.5, 0.5};
    });
    EXPECT_EQ(outside.p_value, 0);
    EXPECT_NE(outside.description.find("sample 500 at (1.5, 0.5) lies outside"), std::string::npos)
        << outside.description;
    const auto nan = chi_square_test(grid, uniform, 1000, [](std::uint64_t) {
        return GridPoint{std::nan(""), 0.5};
    });
    EXPECT_EQ(nan.p_value, 0);
    // A sample where the density is zero.
    auto left_half = uniform;
    for (int b = 5; b < 10; ++b) left_half[b] = 0;
    for (int b = 0; b < 5; ++b) left_half[b] = 0.2;
    const auto impossible = chi_square_test(grid, left_half, 1000, [](std::uint64_t) {
        return GridPoint{0.7, 0.5};
    });
    EXPECT_EQ(impossible.p_value, 0);
    EXPECT_NE(impossible.description.find("where the density is 0"), std::string::npos)
        << impossible.description;
    // A density that integrates to 1.1.
    auto too_much = uniform;
    for (double& p : too_much) p *= 1.1;
    const auto unnormalised = chi_square_test(grid, too_much, 1000, [](std::uint64_t i) {
        return GridPoint{random_float(i, 0, 0, 32), 0.5};
    });
    EXPECT_EQ(unnormalised.p_value, 0);
    EXPECT_NE(unnormalised.description.find("does not integrate to 1"), std::string::npos)
        << unnormalised.description;
}

}  // namespace
}  // namespace glint
