// The cubic and quartic solvers on polynomials built from known roots: simple, close, double,
// triple and widely spread roots, complex pairs, degenerate leading coefficients, random ones.
#include "glint/math/quartic.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

namespace glint {
namespace {

// Coefficients (highest degree first) of lead * prod (t - r_i) * prod (t^2 - 2 re t + |z|^2)
// for the complex pairs re +- i im.
struct Pair {
    double re, im;
};
std::vector<double> from_roots(std::vector<double> roots, std::vector<Pair> pairs = {},
                               double lead = 1) {
    std::vector<double> c{lead};
    const auto multiply = [&c](std::vector<double> factor) {
        std::vector<double> out(c.size() + factor.size() - 1, 0.0);
        for (std::size_t i = 0; i < c.size(); ++i)
            for (std::size_t j = 0; j < factor.size(); ++j) out[i + j] += c[i] * factor[j];
        c = out;
    };
    for (double r : roots) multiply({1, -r});
    for (Pair z : pairs) multiply({1, -2 * z.re, z.re * z.re + z.im * z.im});
    return c;
}

QuarticRoots quartic(const std::vector<double>& c) {
    return solve_quartic(c.at(0), c.at(1), c.at(2), c.at(3), c.at(4));
}
CubicRoots cubic(const std::vector<double>& c) {
    return solve_cubic(c.at(0), c.at(1), c.at(2), c.at(3));
}

template <int N>
std::vector<double> as_vector(const RealRoots<N>& r) {
    return {r.begin(), r.end()};
}

// Each expected root matched in order, within a tolerance relative to its size.
template <int N>
void expect_roots(const RealRoots<N>& actual, std::vector<double> expected, double tolerance) {
    std::sort(expected.begin(), expected.end());
    ASSERT_EQ(actual.count, static_cast<int>(expected.size()))
        << ::testing::PrintToString(as_vector(actual));
    for (int i = 0; i < actual.count; ++i) {
        EXPECT_NEAR(actual[i], expected[i], tolerance * std::max(1.0, std::abs(expected[i])))
            << "root " << i;
    }
}

TEST(Cubic, ThreeSimpleRoots) {
    // (t - 1)(t - 2)(t - 3) = t^3 - 6t^2 + 11t - 6
    expect_roots(solve_cubic(1, -6, 11, -6), {1, 2, 3}, 1e-15);
}

TEST(Cubic, OneRealRootAndAComplexPair) {
    // t^3 - 1 = (t - 1)(t^2 + t + 1)
    expect_roots(solve_cubic(1, 0, 0, -1), {1}, 1e-15);
    // t^3 + t + 1: the real root of Cardano's textbook example, -0.6823278038280193.
    expect_roots(solve_cubic(1, 0, 1, 1), {-0.6823278038280193}, 1e-15);
}

TEST(Cubic, DoubleRootIsListedTwiceAndTripleRootOnce) {
    expect_roots(cubic(from_roots({1, 1, -2})), {-2, 1, 1}, 1e-12);
    expect_roots(cubic(from_roots({0.1, 0.1, 3})), {0.1, 0.1, 3}, 1e-8);
    // (t - 1)^3 crosses zero once; its root is flat, hence the looser tolerance.
    expect_roots(solve_cubic(1, -3, 3, -1), {1}, 1e-5);
}

TEST(Cubic, ZeroLeadingCoefficientGivesTheQuadraticRoots) {
    expect_roots(solve_cubic(0, 1, 1, -6), {-3, 2}, 1e-15);
    expect_roots(solve_cubic(0, 1, -4, 4), {2, 2}, 1e-15);  // a double root, twice
    expect_roots(solve_cubic(0, 0, 2, -4), {2}, 1e-15);     // linear
    EXPECT_TRUE(solve_cubic(0, 0, 0, 1).empty());
}

TEST(Quartic, FourSimpleRoots) {
    // (t - 1)(t - 2)(t - 3)(t - 4) = t^4 - 10t^3 + 35t^2 - 50t + 24. The condition number of
    // the root 2 is sum |c_i| 2^i / |p'(2)| = 360 / 2, so 1e-14 is what double precision allows.
    expect_roots(solve_quartic(1, -10, 35, -50, 24), {1, 2, 3, 4}, 1e-14);
    // The same scaled by -3: the leading coefficient need not be 1 or positive.
    expect_roots(solve_quartic(-3, 30, -105, 150, -72), {1, 2, 3, 4}, 1e-14);
}

TEST(Quartic, ComplexPairsContributeNothing) {
    EXPECT_TRUE(quartic(from_roots({}, {{0, 1}, {0, 2}})).empty());  // (t^2 + 1)(t^2 + 4)
    expect_roots(quartic(from_roots({1, -3}, {{0.5, 1}})), {-3, 1}, 1e-14);
    // A complex pair very close to the real axis is still no real root.
    EXPECT_TRUE(quartic(from_roots({}, {{2, 1e-3}, {-1, 0.5}})).empty());
}

TEST(Quartic, DoubleRootsAreListedTwice) {
    expect_roots(quartic(from_roots({2, 2, -1, 5})), {-1, 2, 2, 5}, 1e-12);
    expect_roots(quartic(from_roots({1, 1, -1, -1})), {-1, -1, 1, 1}, 1e-12);
    // t^4 - t^2 = t^2 (t - 1)(t + 1): a double root at exactly zero.
    expect_roots(solve_quartic(1, 0, -1, 0, 0), {-1, 0, 0, 1}, 1e-15);
    // Coefficients that are not exact in binary: the double root is found to rounding.
    expect_roots(quartic(from_roots({0.3, 0.3, -0.7, 1.9})), {-0.7, 0.3, 0.3, 1.9}, 1e-8);
    // A double root beside a complex pair (a ray grazing a torus: the tangent point).
    expect_roots(quartic(from_roots({0.6, 0.6}, {{-0.2, 0.4}})), {0.6, 0.6}, 1e-8);
}

TEST(Quartic, CloseRootsAreSeparated) {
    // Roots 1e-6 apart: each is found, as accurately as the conditioning allows (about
    // 1e-16 * 30 / |p'(1)| = 1e-16 * 30 / 6e-6 = 5e-10).
    expect_roots(quartic(from_roots({1, 1 + 1e-6, 3, -2})), {-2, 1, 1 + 1e-6, 3}, 1e-9);
    // Three roots 1e-4 apart: |p'| = 1.3e-7 there, so about 1e-8.
    expect_roots(quartic(from_roots({0.5, 0.5 + 1e-4, 0.5 - 1e-4, 7})),
                 {0.5 - 1e-4, 0.5, 0.5 + 1e-4, 7}, 5e-8);
}

TEST(Quartic, TripleAndQuadrupleRootsAreFound) {
    // Odd multiplicity: listed once. The value is flat there, so the root is only good to
    // about the cube (fourth) root of the rounding error.
    const auto triple = quartic(from_roots({1, 1, 1, 2}));
    ASSERT_GE(triple.count, 2);
    EXPECT_NEAR(triple[0], 1, 1e-4);
    EXPECT_NEAR(triple[triple.count - 1], 2, 1e-12);
    const auto quadruple = quartic(from_roots({1, 1, 1, 1}));
    ASSERT_GE(quadruple.count, 1);
    for (double t : quadruple) EXPECT_NEAR(t, 1, 1e-3);
}

TEST(Quartic, WidelySpreadMagnitudesKeepTheirRelativeAccuracy) {
    expect_roots(quartic(from_roots({1e-4, 1, 1e2, 1e4})), {1e-4, 1, 1e2, 1e4}, 1e-13);
    expect_roots(quartic(from_roots({-1e-3, 2e-3, -5e3, 1e5})), {-5e3, -1e-3, 2e-3, 1e5}, 1e-12);
    // The smallest root keeps its relative accuracy too.
    const auto r = quartic(from_roots({1e-4, 1, 1e2, 1e4}));
    ASSERT_EQ(r.count, 4);
    EXPECT_NEAR(r[0], 1e-4, 1e-4 * 1e-13);
}

TEST(Quartic, TinyLeadingCoefficientDegradesGracefullyToTheCubic) {
    // (1e-12 t - 1)(t - 1)(t - 2)(t - 3): three ordinary roots and one at 1e12.
    const auto c = from_roots({1, 2, 3, 1e12}, {}, 1e-12);
    expect_roots(quartic(c), {1, 2, 3, 1e12}, 1e-12);
    // Exactly zero: the cubic's roots.
    expect_roots(solve_quartic(0, 1, -6, 11, -6), {1, 2, 3}, 1e-15);
    // So small that the huge root overflows: the cubic's roots.
    expect_roots(solve_quartic(1e-310, 1e300, -6e300, 11e300, -6e300), {1, 2, 3}, 1e-15);
}

TEST(Quartic, DegenerateAndNonFiniteInputsGiveNoRoots) {
    EXPECT_TRUE(solve_quartic(0, 0, 0, 0, 0).empty());
    EXPECT_TRUE(solve_quartic(0, 0, 0, 0, 1).empty());
    EXPECT_TRUE(solve_quartic(1, NAN, 0, 0, -1).empty());
    EXPECT_TRUE(solve_quartic(INFINITY, 0, 0, 0, -1).empty());
    expect_roots(solve_quartic(2, 0, 0, 0, 0), {0, 0}, 0);  // t^4: touches zero at 0
}

TEST(Quartic, RandomPolynomialsWithKnownRoots) {
    std::mt19937 rng(2024);
    std::uniform_real_distribution<double> uniform(-10, 10);
    std::uniform_int_distribution<int> pairs_of(0, 2);
    for (int i = 0; i < 2000; ++i) {
        const int pairs = pairs_of(rng);
        std::vector<double> roots;
        std::vector<Pair> complex;
        for (int k = 0; k < 4 - 2 * pairs; ++k) roots.push_back(uniform(rng));
        // Keep the imaginary parts clear of zero: those near-real pairs are the close-root
        // tests' business.
        for (int k = 0; k < pairs; ++k)
            complex.push_back({uniform(rng), 0.1 + std::abs(uniform(rng))});
        std::sort(roots.begin(), roots.end());
        double separation = 1e9;
        for (std::size_t k = 1; k < roots.size(); ++k)
            separation = std::min(separation, roots[k] - roots[k - 1]);
        if (separation < 1e-3) continue;
        const double lead = uniform(rng);
        const auto found = quartic(from_roots(roots, complex, lead));
        SCOPED_TRACE(::testing::Message() << "polynomial " << i);
        expect_roots(found, roots, 1e-9);
    }
}

TEST(Quartic, RandomCoefficientsGiveRootsWithTinyResiduals) {
    // No known roots: every reported root must make the polynomial vanish to rounding (backward
    // stability), in ascending order.
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> uniform(-1, 1);
    for (int i = 0; i < 2000; ++i) {
        std::array<double, 5> c;
        for (double& x : c) x = uniform(rng) * std::pow(10.0, 2 * uniform(rng));
        const auto roots = solve_quartic(c[0], c[1], c[2], c[3], c[4]);
        for (double t : roots) {
            double p = 0, magnitude = 0;
            for (double x : c) {
                p = p * t + x;
                magnitude = magnitude * std::abs(t) + std::abs(x);
            }
            EXPECT_LE(std::abs(p), 1e-14 * magnitude) << "polynomial " << i << " root " << t;
        }
        EXPECT_TRUE(std::is_sorted(roots.begin(), roots.end()));
    }
}

}  // namespace
}  // namespace glint
