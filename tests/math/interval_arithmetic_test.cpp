#include "glint/math/interval_arithmetic.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <random>

namespace glint {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The interval holds [lo, hi] and is at most `slack` wider on each side.
void expect_tight(RealInterval r, double lo, double hi, double slack = 1e-12) {
    EXPECT_LE(r.lo, lo) << "lo " << r.lo << " vs " << lo;
    EXPECT_GE(r.lo, lo - slack) << "lo " << r.lo << " vs " << lo;
    EXPECT_GE(r.hi, hi) << "hi " << r.hi << " vs " << hi;
    EXPECT_LE(r.hi, hi + slack) << "hi " << r.hi << " vs " << hi;
}

TEST(IntervalArithmetic, SumsAndProductsOfWorkedIntervals) {
    expect_tight(RealInterval{1, 2} + RealInterval{3, 4}, 4, 6);
    expect_tight(RealInterval{1, 2} - RealInterval{3, 4}, -3, -1);
    expect_tight(RealInterval{-1, 2} * RealInterval{3, 4}, -4, 8);
    expect_tight(RealInterval{-2, -1} * RealInterval{-3, 4}, -8, 6);
    EXPECT_EQ(-RealInterval({1, 2}), RealInterval({-2, -1}));
}

TEST(IntervalArithmetic, RoundsOutwards) {
    // 0.1 + 0.2 rounds up to 0.30000000000000004 in double; the exact sum of the two doubles
    // is below it, so the lower end must be below it too.
    const RealInterval r = RealInterval::point(0.1) + RealInterval::point(0.2);
    EXPECT_LT(r.lo, 0.1 + 0.2);
    EXPECT_GE(r.hi, 0.1 + 0.2);
    EXPECT_TRUE(RealInterval::point(1.0 / 3).contains(1.0 / 3));
    EXPECT_LT((RealInterval::point(1) / RealInterval::point(3)).lo, 1.0 / 3);
    EXPECT_GT((RealInterval::point(1) / RealInterval::point(3)).hi, 1.0 / 3);
}

TEST(IntervalArithmetic, DivisionByIntervalsHoldingZero) {
    expect_tight(RealInterval{1, 2} / RealInterval{2, 4}, 0.25, 1);
    EXPECT_EQ(RealInterval({1, 2}) / RealInterval({-1, 1}), RealInterval::whole());
    const RealInterval right = RealInterval{1, 2} / RealInterval{0, 1};  // [1, +inf]
    EXPECT_LE(right.lo, 1);
    EXPECT_GT(right.lo, 0.99);
    EXPECT_EQ(right.hi, kInf);
    const RealInterval left = RealInterval{-2, -1} / RealInterval{0, 2};  // [-inf, -0.5]
    EXPECT_EQ(left.lo, -kInf);
    EXPECT_GE(left.hi, -0.5);
    EXPECT_LT(left.hi, -0.49);
    EXPECT_TRUE((RealInterval{1, 2} / RealInterval{0, 0}).is_empty());  // x / 0 has no value
    expect_tight(RealInterval{0, 0} / RealInterval{0, 1}, 0, 0);        // 0 / x = 0
}

TEST(IntervalArithmetic, IntegerPowersAreTight) {
    expect_tight(pow(RealInterval{-2, 1}, 2), 0, 4);  // even around 0: from 0
    EXPECT_EQ(pow(RealInterval{-2, 1}, 2).lo, 0);     // exactly: x^2 >= 0
    expect_tight(pow(RealInterval{-2, -1}, 2), 1, 4);
    expect_tight(pow(RealInterval{-2, 1}, 3), -8, 1);  // odd: monotonic
    expect_tight(pow(RealInterval{1, 2}, -1), 0.5, 1);
    const RealInterval pole = pow(RealInterval{-1, 1}, -2);  // 1/x^2 on [-1, 1]: [1, inf]
    EXPECT_LE(pole.lo, 1);
    EXPECT_EQ(pole.hi, kInf);
    EXPECT_EQ(pow(RealInterval{-5, 5}, 0), (RealInterval{1, 1}));
    // The dependency problem x * x vs x^2: the product cannot know both factors are equal.
    expect_tight(RealInterval{-2, 1} * RealInterval{-2, 1}, -2, 4);
}

TEST(IntervalArithmetic, FractionalAndIntervalPowers) {
    expect_tight(pow(RealInterval{-1, 4}, 0.5), 0, 2);                  // defined for x >= 0 only
    const RealInterval negative_power = pow(RealInterval{0, 4}, -0.5);  // [0.5, inf]
    EXPECT_LE(negative_power.lo, 0.5);
    EXPECT_EQ(negative_power.hi, kInf);
    EXPECT_TRUE(pow(RealInterval{-4, -1}, 0.5).is_empty());
    expect_tight(pow(RealInterval{1, 4}, RealInterval{0.5, 2}), 1, 16, 1e-11);
    expect_tight(pow(RealInterval{0, 1}, RealInterval{0.5, 2}), 0, 1);
    const RealInterval both = pow(RealInterval{0, 1}, RealInterval{-1, 1});  // 0^-1 = inf
    EXPECT_LE(both.lo, 0);
    EXPECT_EQ(both.hi, kInf);
    // (-2)^2 = 4 exists: a negative base with an exponent range holding an integer.
    EXPECT_EQ(pow(RealInterval{-2, 2}, RealInterval{1.5, 2.5}), RealInterval::whole());
    // No integer exponent in [1.2, 1.8]: only the bases >= 0 have real powers.
    expect_tight(pow(RealInterval{-2, 2}, RealInterval{1.2, 1.8}), 0, std::pow(2, 1.8), 1e-11);
    expect_tight(pow(RealInterval{-2, 3}, RealInterval{2, 2}), 0, 9);  // point exponent: x^2
}

TEST(IntervalArithmetic, ElementaryFunctionsOnTheirDomains) {
    expect_tight(sqrt(RealInterval{-4, 9}), 0, 3);
    EXPECT_TRUE(sqrt(RealInterval{-4, -1}).is_empty());
    const RealInterval l = log(RealInterval{0, std::numbers::e});
    EXPECT_EQ(l.lo, -kInf);
    EXPECT_NEAR(l.hi, 1, 1e-12);
    EXPECT_TRUE(log(RealInterval{-1, 0}).is_empty());
    expect_tight(exp(RealInterval{0, 1}), 1, std::numbers::e);
    expect_tight(abs(RealInterval{-3, 2}), 0, 3);
    expect_tight(min(RealInterval{0, 5}, RealInterval{1, 2}), 0, 2);
    expect_tight(max(RealInterval{0, 5}, RealInterval{1, 2}), 1, 5);
}

TEST(IntervalArithmetic, SineAndCosineFindTheirExtrema) {
    constexpr double pi = std::numbers::pi;
    expect_tight(sin(RealInterval{0, pi}), 0, 1);
    expect_tight(sin(RealInterval{pi / 4, 3 * pi / 4}), std::sin(pi / 4), 1);
    expect_tight(sin(RealInterval{0.1, 0.2}), std::sin(0.1), std::sin(0.2));
    expect_tight(cos(RealInterval{-0.5, 0.5}), std::cos(0.5), 1);
    expect_tight(cos(RealInterval{3, 4}), -1, std::max(std::cos(3.0), std::cos(4.0)));
    expect_tight(sin(RealInterval{1000 * pi + 1, 1000 * pi + 2}), std::sin(1.0), 1, 1e-9);
    EXPECT_EQ(sin(RealInterval{0, 7}), (RealInterval{-1, 1}));
    EXPECT_EQ(cos(RealInterval{1e20, 1e20}), (RealInterval{-1, 1}));  // beyond reduction
    EXPECT_EQ(sin(RealInterval::whole()), (RealInterval{-1, 1}));
}

TEST(IntervalArithmetic, EmptyPropagates) {
    const RealInterval e = RealInterval::empty();
    EXPECT_TRUE(e.is_empty());
    EXPECT_TRUE(e.excludes_zero());
    EXPECT_TRUE((e + RealInterval{1, 2}).is_empty());
    EXPECT_TRUE((RealInterval{1, 2} * e).is_empty());
    EXPECT_TRUE(sin(e).is_empty());
    EXPECT_TRUE(min(e, RealInterval{0, 1}).is_empty());
    EXPECT_EQ(hull(e, RealInterval{1, 2}), (RealInterval{1, 2}));
    EXPECT_TRUE(intersect(RealInterval{0, 1}, RealInterval{2, 3}).is_empty());
}

TEST(IntervalArithmetic, InfiniteEndpointsGiveNoNaN) {
    const RealInterval w = RealInterval::whole();
    for (const RealInterval r :
         {w + w, w - w, w * w, w * RealInterval{0, 0}, w / w, exp(w), log(w), sqrt(w), pow(w, 3),
          pow(w, -2), pow(w, 0.5), pow(w, w), RealInterval{-kInf, 0} * RealInterval{0, kInf}}) {
        EXPECT_FALSE(std::isnan(r.lo));
        EXPECT_FALSE(std::isnan(r.hi));
    }
    const RealInterval zero = w * RealInterval{0, 0};  // 0 * x = 0 even for unbounded x
    EXPECT_TRUE(zero.contains(0));
    EXPECT_LT(zero.width(), 1e-300);
    // Overflow: the lower end of [1e300, 1e300]^2 is finite (a true lower bound).
    const RealInterval big = pow(RealInterval{1e300, 1e300}, 2);
    EXPECT_TRUE(std::isfinite(big.lo));
    EXPECT_EQ(big.hi, kInf);
}

// The defining property: for random intervals and random points inside them, the function of
// the points lies in the function of the intervals.
// atan2: the angles of a box's corners where it keeps clear of the origin and of the jump along
// the negative x axis; the whole [-pi, pi] where it does not.
TEST(IntervalArithmetic, Atan2TakesTheCornersAnglesAwayFromItsJump) {
    const double pi = std::acos(-1.0);
    const RealInterval first = atan2(RealInterval{1, 2}, RealInterval{1, 2});  // y, x
    EXPECT_NEAR(first.lo, std::atan2(1, 2), 1e-15);
    EXPECT_NEAR(first.hi, std::atan2(2, 1), 1e-15);
    EXPECT_LE(first.lo, std::atan2(1, 2));
    // Across the positive x axis: continuous, from -pi/4 to pi/4.
    const RealInterval across = atan2(RealInterval{-1, 1}, RealInterval{1, 3});
    EXPECT_NEAR(across.lo, -pi / 4, 1e-15);
    EXPECT_NEAR(across.hi, pi / 4, 1e-15);
    EXPECT_TRUE(atan2_continuous({-1, 1}, {1, 3}));
    // Across the negative x axis, or round the origin: every angle.
    EXPECT_FALSE(atan2_continuous({-1, 1}, {-3, -1}));
    EXPECT_FALSE(atan2_continuous({-1, 1}, {-1, 1}));
    const RealInterval jump = atan2(RealInterval{-1, 1}, RealInterval{-3, -1});
    EXPECT_LE(jump.lo, -pi);
    EXPECT_GE(jump.hi, pi);
    // Above the negative x axis, clear of it: between the angles of (-0.5, 1) and (-1, 0.5).
    const RealInterval left = atan2(RealInterval{0.5, 1}, RealInterval{-1, -0.5});
    EXPECT_NEAR(left.lo, std::atan2(1, -0.5), 1e-14);
    EXPECT_NEAR(left.hi, std::atan2(0.5, -1), 1e-14);
    EXPECT_TRUE(atan2(RealInterval::empty(), RealInterval{1, 2}).is_empty());
}

TEST(IntervalArithmetic, EveryOperationEnclosesItsPointValues) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> endpoint(-6, 6), unit(0, 1);
    const auto random_interval = [&] {
        double a = endpoint(rng), b = endpoint(rng);
        if (unit(rng) < 0.1) b = a;  // points, too
        return RealInterval{std::min(a, b), std::max(a, b)};
    };
    const auto inside = [&](RealInterval r) { return r.lo + unit(rng) * (r.hi - r.lo); };
    using Unary = std::pair<std::function<RealInterval(RealInterval)>, double (*)(double)>;
    const std::vector<Unary> unary{
        {[](RealInterval a) { return -a; }, [](double x) { return -x; }},
        {[](RealInterval a) { return sqrt(a); }, [](double x) { return std::sqrt(x); }},
        {[](RealInterval a) { return exp(a); }, [](double x) { return std::exp(x); }},
        {[](RealInterval a) { return log(a); }, [](double x) { return std::log(x); }},
        {[](RealInterval a) { return sin(a); }, [](double x) { return std::sin(x); }},
        {[](RealInterval a) { return cos(a); }, [](double x) { return std::cos(x); }},
        {[](RealInterval a) { return abs(a); }, [](double x) { return std::abs(x); }},
        {[](RealInterval a) { return pow(a, 2); }, [](double x) { return x * x; }},
        {[](RealInterval a) { return pow(a, 3); }, [](double x) { return x * x * x; }},
        {[](RealInterval a) { return pow(a, -2); }, [](double x) { return 1 / (x * x); }},
        {[](RealInterval a) { return pow(a, 2.5); }, [](double x) { return std::pow(x, 2.5); }},
        {[](RealInterval a) { return pow(a, -0.5); }, [](double x) { return std::pow(x, -0.5); }},
    };
    using Binary = std::pair<std::function<RealInterval(RealInterval, RealInterval)>,
                             double (*)(double, double)>;
    const std::vector<Binary> binary{
        {[](RealInterval a, RealInterval b) { return a + b; },
         [](double x, double y) { return x + y; }},
        {[](RealInterval a, RealInterval b) { return a - b; },
         [](double x, double y) { return x - y; }},
        {[](RealInterval a, RealInterval b) { return a * b; },
         [](double x, double y) { return x * y; }},
        {[](RealInterval a, RealInterval b) { return a / b; },
         [](double x, double y) { return x / y; }},
        {[](RealInterval a, RealInterval b) { return pow(a, b); },
         [](double x, double y) { return std::pow(x, y); }},
        {[](RealInterval a, RealInterval b) { return min(a, b); },
         [](double x, double y) { return std::min(x, y); }},
        {[](RealInterval a, RealInterval b) { return max(a, b); },
         [](double x, double y) { return std::max(x, y); }},
        {[](RealInterval a, RealInterval b) { return atan2(a, b); },
         [](double x, double y) { return std::atan2(x, y); }},
    };
    // Only finite values count: NaN is "undefined here", +-inf a pole, neither a value.
    for (int i = 0; i < 3000; ++i) {
        const RealInterval a = random_interval(), b = random_interval();
        for (std::size_t k = 0; k < unary.size(); ++k) {
            const RealInterval r = unary[k].first(a);
            for (int j = 0; j < 4; ++j) {
                const double x = inside(a), v = unary[k].second(x);
                if (std::isfinite(v)) {
                    ASSERT_TRUE(r.contains(v)) << "unary " << k << " at " << x;
                }
            }
        }
        for (std::size_t k = 0; k < binary.size(); ++k) {
            const RealInterval r = binary[k].first(a, b);
            for (int j = 0; j < 4; ++j) {
                const double x = inside(a), y = inside(b), v = binary[k].second(x, y);
                if (std::isfinite(v)) {
                    ASSERT_TRUE(r.contains(v)) << "binary " << k << " at " << x << ", " << y;
                }
            }
        }
    }
}

}  // namespace
}  // namespace glint
