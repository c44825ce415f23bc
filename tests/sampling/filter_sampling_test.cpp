// Filter importance sampling: positions follow |f| (chi-square), weights f over the density make
// weighted means the filter's own weighted integrals, and the box keeps its positions exact.
#include "glint/sampling/filter_sampling.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "chi_square.h"
#include "glint/sampling/random.h"

namespace glint::filter_sampling_test {
namespace {

constexpr std::uint64_t kSamples = 1'000'000;
constexpr float kAlmostOne = 0x1.fffffep-1f;

// Four chi-square tests here; together they falsely fail with probability 1%.
const double kSignificance = sidak_significance(0.01, 4);

FilterSpec spec_of(FilterKind kind, float radius = -1) {
    FilterSpec spec;
    spec.kind = kind;
    spec.radius = radius > 0 ? radius : default_filter_radius(kind);
    return spec;
}

const FilterKind kKinds[] = {FilterKind::box, FilterKind::tent, FilterKind::gaussian,
                             FilterKind::mitchell};

TEST(FilterSampling, TheOnePixelBoxKeepsThePixelNumbersAsThePosition) {
    const FilterSampling box(spec_of(FilterKind::box));
    for (const Point2 u : {Point2{0, 0}, Point2{0.25f, 0.75f}, Point2{kAlmostOne, 1e-30f}}) {
        const FilterSample s = box.sample(u);
        EXPECT_EQ(s.position, u);
        EXPECT_EQ(s.weight, 1);
    }
}

TEST(FilterSampling, AWiderBoxSpreadsThePixelNumbersEvenly) {
    // Radius 1: from 1/2 - 1 to 1/2 + 1, u = 0.75 at 1/2 + 0.5.
    const FilterSampling box(spec_of(FilterKind::box, 1));
    const FilterSample s = box.sample({0.75f, 0});
    EXPECT_EQ(s.position.x, 1.0f);
    EXPECT_EQ(s.position.y, -0.5f);
    EXPECT_EQ(s.weight, 1);
    EXPECT_FLOAT_EQ(box.pdf(0.3f), 0.5f);
    EXPECT_EQ(box.pdf(1.01f), 0);
}

TEST(FilterSampling, PositionsStayWithinTheRadiusWithFiniteWeights) {
    for (const FilterKind kind : kKinds) {
        const FilterSampling f(spec_of(kind));
        const float r = default_filter_radius(kind);
        for (const float u : {0.0f, 1e-30f, 0.5f, 0.25f, kAlmostOne}) {
            const FilterSample s = f.sample({u, u});
            EXPECT_GE(s.position.x, 0.5f - r) << int(kind) << " u " << u;
            EXPECT_LE(s.position.x, 0.5f + r) << int(kind) << " u " << u;
            EXPECT_TRUE(std::isfinite(s.weight)) << int(kind) << " u " << u;
        }
    }
}

TEST(FilterSampling, TheDensityIntegratesToOne) {
    for (const FilterKind kind : kKinds) {
        const FilterSampling f(spec_of(kind));
        const float r = default_filter_radius(kind);
        double sum = 0;
        constexpr int n = 100000;
        for (int i = 0; i < n; ++i) sum += f.pdf(-r + 2 * r * (float(i) + 0.5f) / n);
        EXPECT_NEAR(sum * 2 * r / n, 1, 1e-4) << int(kind);
    }
}

TEST(FilterSampling, TheDensityFollowsTheFilter) {
    // Gaussian of radius 1.5, sigma 0.5: |f| at 0 and 0.5 in the ratio of (1 - e^-4.5) to
    // (e^-0.5 - e^-4.5), as the density's knots are.
    const FilterSampling g(spec_of(FilterKind::gaussian));
    const double floor = std::exp(-4.5);
    EXPECT_NEAR(g.pdf(0.5f) / g.pdf(0), (std::exp(-0.5) - floor) / (1 - floor), 1e-5);
    // Mitchell's density is |f|: its lobe beyond 1 pixel (radius 2) is sampled too.
    const FilterSampling m(spec_of(FilterKind::mitchell));
    EXPECT_GT(m.pdf(1.5f), 0);
    EXPECT_EQ(m.pdf(2.01f), 0);
}

TEST(FilterSampling, PositionsFollowTheirDensity) {
    for (const FilterKind kind : kKinds) {
        const FilterSampling f(spec_of(kind));
        const double r = default_filter_radius(kind);
        // Along x; y is drawn the same way.
        const ChiSquareGrid grid{0.5 - r, 0.5 + r, 60, 0, 1, 1};
        const auto probabilities = bin_probabilities_midpoint(
            grid, [&](double x, double) { return double(f.pdf(float(x - 0.5))); }, 256);
        const auto result = chi_square_test(grid, probabilities, kSamples, [&](std::uint64_t i) {
            const Point2 u{random_float(i, 0, 0, 7), random_float(i, 0, 1, 7)};
            return GridPoint{f.sample(u).position.x, 0.5};
        });
        EXPECT_GT(result.p_value, kSignificance) << int(kind) << ": " << result.description;
    }
}

TEST(FilterSampling, WeightsAreOneWhereTheDensityIsTheFilter) {
    // The tent is linear between knots: its weights are 1 to rounding. The Gaussian's curve
    // bends between knots 1/64 pixel apart: within 0.2%.
    const FilterSampling tent(spec_of(FilterKind::tent)), gauss(spec_of(FilterKind::gaussian));
    for (int i = 0; i < 1000; ++i) {
        const Point2 u{(float(i) + 0.5f) / 1000, 0.5f};
        EXPECT_NEAR(tent.sample(u).weight, 1, 1e-4) << u.x;
        EXPECT_NEAR(gauss.sample(u).weight, 1, 2e-3) << u.x;
    }
}

TEST(FilterSampling, MitchellsLobesWeighNegatively) {
    const FilterSampling m(spec_of(FilterKind::mitchell));
    int negative = 0;
    for (int i = 0; i < 1000; ++i) {
        const FilterSample s = m.sample({(float(i) + 0.5f) / 1000, 0.5f});
        const float x = s.position.x - 0.5f;
        // With B = C = 1/3 the cubic is (x - 2)^2 (8/3 - 7x/3) / 6 on [1, 2]: negative beyond
        // x = 8/7, which the radius of 2 leaves where it is.
        if (std::abs(x) > 8 / 7.0f + 0.01f) {
            EXPECT_LT(s.weight, 0) << x;
        }
        if (std::abs(x) < 8 / 7.0f - 0.01f) {
            EXPECT_GT(s.weight, 0) << x;
        }
        negative += s.weight < 0;
    }
    EXPECT_GT(negative, 0);
}

// The point of the weights: a weighted mean of g over the samples is the filter's weighted mean
// of g, integral f g / integral f, with g = x^2 + x (odd and even parts) along one axis.
TEST(FilterSampling, WeightedMeansAreTheFiltersWeightedMeans) {
    for (const FilterKind kind : kKinds) {
        const FilterSpec spec = spec_of(kind);
        const Filter filter(spec);
        const FilterSampling f(spec);
        const auto g = [](double x) { return x * x + x; };
        const double r = spec.radius;
        double fg = 0, ff = 0;
        constexpr int n = 200000;
        for (int i = 0; i < n; ++i) {
            const double x = -r + 2 * r * (i + 0.5) / n;
            fg += filter.evaluate(float(x)) * g(x);
            ff += filter.evaluate(float(x));
        }
        // Stratified numbers in x, one y: the estimate's error is far below the tolerance.
        double wg = 0, w = 0;
        for (int i = 0; i < n; ++i) {
            const FilterSample s = f.sample({(float(i) + 0.5f) / n, 0.5f});
            const double x = s.position.x - 0.5;
            wg += s.weight * g(x);
            w += s.weight;
        }
        EXPECT_NEAR(wg / w, fg / ff, 1e-4) << int(kind);
    }
}

}  // namespace
}  // namespace glint::filter_sampling_test
