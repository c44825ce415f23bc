#include "glint/sampling/distribution_2d.h"

#include <gtest/gtest.h>

#include <vector>

#include "chi_square.h"
#include "glint/sampling/random.h"

namespace glint {
namespace {

// 3 x 2 cells, row by row: weights 1 2 0 / 0 0 5, summing to 8.
const std::vector<float> kWeights{1, 2, 0, 0, 0, 5};

TEST(Distribution2D, TheDensityIsEachCellsShareOverItsArea) {
    const Distribution2D d(kWeights, 3, 2);
    // A cell is 1/3 x 1/2 of the square: density = (w / 8) / (1/6).
    EXPECT_FLOAT_EQ(d.pdf({0.1f, 0.2f}), 1.0f / 8 * 6);
    EXPECT_FLOAT_EQ(d.pdf({0.5f, 0.4f}), 2.0f / 8 * 6);
    EXPECT_EQ(d.pdf({0.9f, 0.2f}), 0);
    EXPECT_EQ(d.pdf({0.2f, 0.7f}), 0);
    EXPECT_FLOAT_EQ(d.pdf({0.9f, 0.9f}), 5.0f / 8 * 6);
    // The edges belong to the cells inside.
    EXPECT_FLOAT_EQ(d.pdf({1, 1}), 5.0f / 8 * 6);
}

TEST(Distribution2D, SamplesFollowTheDensityAndMissEmptyCells) {
    const Distribution2D d(kWeights, 3, 2);
    const ChiSquareGrid grid{0, 1, 12, 0, 1, 8};
    const auto p = bin_probabilities_midpoint(grid, [&](double x, double y) {
        return double(d.pdf({float(x), float(y)}));
    });
    const auto r = chi_square_test(grid, p, 200000, [&](std::uint64_t i) {
        float pdf = -1;
        const Point2 q = d.sample({random_float(i, 0, 0, 7), random_float(i, 0, 1, 7)}, &pdf);
        EXPECT_FLOAT_EQ(pdf, d.pdf(q));
        return GridPoint{q.x, q.y};
    });
    EXPECT_GT(r.p_value, 0.01) << r.description;
}

TEST(Distribution2D, ARowOfNothingIsNeverPicked) {
    const Distribution2D d(std::vector<float>{0, 0, 1, 3}, 2, 2);
    for (const float v : {0.0f, 0.3f, 0.99f}) {
        float pdf = 0;
        const Point2 q = d.sample({0.5f, v}, &pdf);
        EXPECT_GE(q.y, 0.5f);
        EXPECT_GT(pdf, 0);
    }
}

}  // namespace
}  // namespace glint
