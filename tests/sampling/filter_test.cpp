// The reconstruction filters' profiles against their formulas, with worked numbers.
#include "glint/sampling/filter.h"

#include <gtest/gtest.h>

#include <cmath>

namespace glint {
namespace {

Filter make(FilterKind kind, float radius = -1) {
    FilterSpec spec;
    spec.kind = kind;
    spec.radius = radius > 0 ? radius : default_filter_radius(kind);
    return Filter(spec);
}

TEST(Filter, EveryFilterIsOneAtTheCentreAndZeroAtTheRadius) {
    for (const FilterKind kind :
         {FilterKind::box, FilterKind::tent, FilterKind::gaussian, FilterKind::mitchell}) {
        const Filter f = make(kind);
        EXPECT_FLOAT_EQ(f.evaluate(0), 1);
        EXPECT_EQ(f.evaluate(f.radius() + 0.01f), 0);
        EXPECT_EQ(f.evaluate(-f.radius() - 0.01f), 0);
    }
}

TEST(Filter, BoxTakesOneSideOfItsBorder) {
    const Filter box = make(FilterKind::box);
    EXPECT_EQ(box.evaluate(0.5f), 1);
    EXPECT_EQ(box.evaluate(-0.5f), 0);
    EXPECT_EQ(box.evaluate(0.49f), 1);
}

TEST(Filter, TentFallsLinearly) {
    const Filter tent = make(FilterKind::tent, 2);
    EXPECT_FLOAT_EQ(tent.evaluate(0.5f), 0.75f);
    EXPECT_FLOAT_EQ(tent.evaluate(-1.5f), 0.25f);
}

TEST(Filter, GaussianIsShiftedToReachZeroAtTheRadius) {
    // (exp(-x^2 / 2 sigma^2) - exp(-r^2 / 2 sigma^2)) / (1 - exp(-r^2 / 2 sigma^2)) with sigma
    // 0.5 and radius 1.5: at x = 0.5, (e^-0.5 - e^-4.5) / (1 - e^-4.5).
    const Filter g = make(FilterKind::gaussian);
    const double floor = std::exp(-4.5);
    EXPECT_NEAR(g.evaluate(0.5f), (std::exp(-0.5) - floor) / (1 - floor), 1e-6);
    EXPECT_NEAR(g.evaluate(1.0f), (std::exp(-2.0) - floor) / (1 - floor), 1e-6);
}

TEST(Filter, MitchellHasItsNegativeLobe) {
    // B = C = 1/3 on [-2, 2], scaled by 1 / k(0) = 6 / (6 - 2B) = 9/8. At x = 1 (radius 2, so
    // the cubic's argument is 1): k(1) = ((12 - 9B - 6C) + (-18 + 12B + 6C) + (6 - 2B)) / 6
    // = (7 - 12 + 16/3) / 6 = 1/18; beyond it the lobe is negative.
    const Filter m = make(FilterKind::mitchell);
    EXPECT_NEAR(m.evaluate(1.0f), (1 / 18.0) * 9 / 8, 1e-6);
    EXPECT_LT(m.evaluate(1.5f), 0);
    EXPECT_EQ(m.evaluate(2.0f), 0);
}

TEST(Filter, ProblemsAreDescribed) {
    FilterSpec spec;
    spec.radius = 0.2f;
    EXPECT_EQ(describe_problem(spec), "filter radius must be in [0.5, 8], got 0.2");
    spec.radius = 1.5f;
    spec.kind = FilterKind::gaussian;
    spec.sigma = 2;
    EXPECT_EQ(describe_problem(spec),
              "gaussian filter sigma must be in (0, radius] = (0, 1.5], got 2");
    spec.sigma = 0.5f;
    EXPECT_EQ(describe_problem(spec), "");
}

TEST(Filter, NamesRoundTrip) {
    for (const std::string_view name : filter_names()) EXPECT_TRUE(filter_from_name(name));
    EXPECT_EQ(filter_from_name("mitchell"), FilterKind::mitchell);
    EXPECT_FALSE(filter_from_name("lanczos"));
}

}  // namespace
}  // namespace glint
