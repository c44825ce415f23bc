#include "glint/sampling/discrete_distribution.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "chi_square.h"
#include "glint/sampling/random.h"

namespace glint {
namespace {

constexpr float kAlmostOne = 0x1.fffffep-1f;  // the largest float below 1

TEST(DiscreteDistribution, ProbabilitiesAreTheNormalisedWeights) {
    const DiscreteDistribution d(std::vector<float>{1, 0, 3});
    EXPECT_EQ(d.size(), 3u);
    EXPECT_FLOAT_EQ(d.total(), 4);
    EXPECT_FLOAT_EQ(d.probability(0), 0.25f);
    EXPECT_EQ(d.probability(1), 0);
    EXPECT_FLOAT_EQ(d.probability(2), 0.75f);
}

TEST(DiscreteDistribution, SamplePicksByTheCdfAndRemapsU) {
    // Weights 1, 0, 3: item 0 owns [0, 0.25), item 2 owns [0.25, 1).
    const DiscreteDistribution d(std::vector<float>{1, 0, 3});
    float r = -1;
    EXPECT_EQ(d.sample(0, &r), 0u);
    EXPECT_EQ(r, 0);
    EXPECT_EQ(d.sample(0.2f, &r), 0u);
    EXPECT_NEAR(r, 0.8f, 1e-6f);
    EXPECT_EQ(d.sample(0.25f, &r), 2u);  // the zero-width interval of item 1 is skipped
    EXPECT_EQ(r, 0);
    EXPECT_EQ(d.sample(0.5f, &r), 2u);
    EXPECT_NEAR(r, 1 / 3.0f, 1e-6f);
    EXPECT_EQ(d.sample(kAlmostOne, &r), 2u);
    EXPECT_LT(r, 1);
    EXPECT_EQ(d.sample(0.1f), 0u);  // without remapping
}

TEST(DiscreteDistribution, OutOfRangeUIsClampedAndZeroWeightsAreNeverPicked) {
    const DiscreteDistribution d(std::vector<float>{0, 2, 0});
    float r = -1;
    for (float u : {0.0f, 0.3f, 0.999f, kAlmostOne, 1.0f, 2.0f, -0.5f}) {
        EXPECT_EQ(d.sample(u, &r), 1u) << u;
        EXPECT_GE(r, 0);
        EXPECT_LT(r, 1);
    }
    EXPECT_NEAR((d.sample(0.3f, &r), r), 0.3f, 1e-7f);  // the only item: u passes through
}

TEST(DiscreteDistribution, RejectsWeightsThatDefineNoDistribution) {
    const float inf = std::numeric_limits<float>::infinity();
    EXPECT_THROW(DiscreteDistribution(std::vector<float>{}), std::invalid_argument);
    EXPECT_THROW(DiscreteDistribution(std::vector<float>{0, 0, 0}), std::invalid_argument);
    EXPECT_THROW(DiscreteDistribution(std::vector<float>{1, -1}), std::invalid_argument);
    EXPECT_THROW(DiscreteDistribution(std::vector<float>{1, std::nanf("")}), std::invalid_argument);
    EXPECT_THROW(DiscreteDistribution(std::vector<float>{1, inf}), std::invalid_argument);
    try {
        DiscreteDistribution(std::vector<float>{1, 2, -3});
        FAIL() << "no exception";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("weight 2"), std::string::npos) << e.what();
    }
}

TEST(DiscreteDistribution, AMillionSmallWeightsStayAccurate) {
    // A float running sum of a million 1e-3 would drift by about 1e-3 relative; the double
    // table does not.
    const std::vector<float> weights(1'000'000, 1e-3f);
    const DiscreteDistribution d(weights);
    EXPECT_NEAR(d.total(), 1000, 1e-3);
    EXPECT_NEAR(d.probability(123456), 1e-6, 1e-12);
    EXPECT_NEAR(double(d.sample(0.5f)), 500000, 1);
    EXPECT_EQ(d.sample(0), 0u);
    EXPECT_EQ(d.sample(kAlmostOne), 999999u);
}

TEST(DiscreteDistribution, IndicesAndRemappedUFollowTheirDensity) {
    // The pair (index, remapped u) must be distributed as P(i) x uniform: remapping must not
    // depend on which item was picked.
    const std::vector<float> weights = {1, 0, 3, 0.5f, 2.5f, 7, 0, 1};
    const DiscreteDistribution d(weights);
    const ChiSquareGrid grid{0, 8, 8, 0, 1, 10};
    const double total = 15;
    const auto probabilities =
        bin_probabilities(grid, [&](double x0, double, double y0, double y1) {
            return weights[int(x0 + 0.5)] / total * (y1 - y0);
        });
    const auto r = chi_square_test(grid, probabilities, 1'000'000, [&](std::uint64_t i) {
        float remapped;
        const std::size_t index = d.sample(random_float(i, 0, 0, 21), &remapped);
        return GridPoint{double(index) + 0.5, remapped};
    });
    EXPECT_GT(r.p_value, 0.01) << r.description;  // the only chi-square test of this file
}

}  // namespace
}  // namespace glint
