// Pearson's chi-square goodness-of-fit test for warps: do a warp's samples follow the density it
// claims? Samples are counted into a grid over a 2D parameterisation of the domain and compared
// with the density integrated over each bin (the approach of Mitsuba's and pbrt's warp tests).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace glint {

// ---- the distribution of the statistic ---------------------------------------------------------

// The regularised upper incomplete gamma function Q(a, x) = Gamma(a, x) / Gamma(a), a > 0, x >= 0.
// Below x = a + 1 the power series of P = 1 - Q converges fast; above, the continued fraction of
// Q does (evaluated by the modified Lentz method). Press et al., Numerical Recipes, sec. 6.2.
inline double regularized_upper_gamma(double a, double x) {
    if (x <= 0) return 1;
    // log(e^-x x^a / Gamma(a)), the factor common to both forms.
    const double log_prefix = -x + a * std::log(x) - std::lgamma(a);
    constexpr double kEpsilon = 1e-15;
    constexpr int kMaxTerms = 100000;
    if (x < a + 1) {
        // P(a, x) = e^-x x^a / Gamma(a) * sum_{n>=0} x^n / (a (a+1) ... (a+n)).
        double term = 1 / a, sum = term;
        for (int n = 1; n < kMaxTerms && term > sum * kEpsilon; ++n) {
            term *= x / (a + n);
            sum += term;
        }
        return std::clamp(1 - sum * std::exp(log_prefix), 0.0, 1.0);
    }
    // Q(a, x) = e^-x x^a / Gamma(a) / f with f = b0 + a1/(b1 + a2/(b2 + ...)),
    // b_i = x + 2i + 1 - a and a_i = -i (i - a).
    constexpr double kTiny = 1e-300;
    double f = x + 1 - a;
    if (std::abs(f) < kTiny) f = kTiny;
    double c = f, d = 0;
    for (int i = 1; i < kMaxTerms; ++i) {
        const double a_i = -i * (i - a), b_i = x + 2 * i + 1 - a;
        d = b_i + a_i * d;
        if (std::abs(d) < kTiny) d = kTiny;
        c = b_i + a_i / c;
        if (std::abs(c) < kTiny) c = kTiny;
        d = 1 / d;
        const double delta = c * d;
        f *= delta;
        if (std::abs(delta - 1) < kEpsilon) break;
    }
    return std::clamp(std::exp(log_prefix) / f, 0.0, 1.0);
}

// The probability that a chi-square variable with `dof` degrees of freedom reaches `statistic`.
inline double chi_square_p_value(double statistic, int dof) {
    return regularized_upper_gamma(0.5 * dof, 0.5 * statistic);
}

// The per-test significance that keeps the chance of any false failure among `test_count`
// independent tests at `family_alpha` (Sidak): 1 - (1 - alpha)^(1/m), about alpha / m.
inline double sidak_significance(double family_alpha, int test_count) {
    return -std::expm1(std::log1p(-family_alpha) / test_count);
}

// ---- integrating the density over a bin ------------------------------------------------------

namespace detail {

template <class F>
double simpson_step(const F& f, double a, double b, double fa, double fm, double fb, double whole,
                    double tolerance, int depth) {
    const double m = 0.5 * (a + b), lm = 0.5 * (a + m), rm = 0.5 * (m + b);
    const double flm = f(lm), frm = f(rm);
    const double left = (m - a) / 6 * (fa + 4 * flm + fm);
    const double right = (b - m) / 6 * (fm + 4 * frm + fb);
    const double delta = left + right - whole;
    // Richardson: the error of the halved rule is about delta / 15.
    if (depth <= 0 || std::abs(delta) <= 15 * tolerance) return left + right + delta / 15;
    return simpson_step(f, a, m, fa, flm, fm, left, tolerance / 2, depth - 1) +
           simpson_step(f, m, b, fm, frm, fb, right, tolerance / 2, depth - 1);
}

}  // namespace detail

// The integral of a smooth f over [a, b] to about `tolerance` (absolute), by adaptive Simpson.
// A function that vanishes at all five first nodes may be missed: use it for smooth densities
// and midpoint_2d for densities with edges inside a bin.
template <class F>
double adaptive_simpson(const F& f, double a, double b, double tolerance, int max_depth = 16) {
    const double fa = f(a), fm = f(0.5 * (a + b)), fb = f(b);
    const double whole = (b - a) / 6 * (fa + 4 * fm + fb);
    return detail::simpson_step(f, a, b, fa, fm, fb, whole, tolerance, max_depth);
}

// The integral of a smooth f(x, y) over [x0, x1] x [y0, y1] by nested adaptive Simpson.
template <class F>
double adaptive_simpson_2d(const F& f, double x0, double x1, double y0, double y1,
                           double tolerance) {
    // Inner integrals ten times finer, so their noise does not drive the outer refinement.
    const double inner_tolerance = 0.1 * tolerance / (y1 - y0);
    const auto row = [&](double y) {
        const auto along_row = [&f, y](double x) { return f(x, y); };
        return adaptive_simpson(along_row, x0, x1, inner_tolerance);
    };
    return adaptive_simpson(row, y0, y1, tolerance);
}

// The integral of f(x, y) over [x0, x1] x [y0, y1] by the midpoint rule on n x n cells. Robust
// for indicator-like densities (disks, polygons) whose edges cross the rectangle: the error is
// confined to the cells the edge crosses.
template <class F>
double midpoint_2d(const F& f, double x0, double x1, double y0, double y1, int n) {
    const double dx = (x1 - x0) / n, dy = (y1 - y0) / n;
    double sum = 0;
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) sum += f(x0 + (i + 0.5) * dx, y0 + (j + 0.5) * dy);
    }
    return sum * dx * dy;
}

// ---- the grid, the histogram and the test ---------------------------------------------------

// A point of the 2D parameterisation: (cos theta, phi) or (theta, phi) for directions, (x, y)
// for planar points, (lambda, anything) for 1D quantities.
struct GridPoint {
    double x = 0, y = 0;
};

// x_bins x y_bins equal bins over [x_min, x_max] x [y_min, y_max], numbered x fastest.
struct ChiSquareGrid {
    double x_min, x_max;
    int x_bins;
    double y_min, y_max;
    int y_bins;

    int bin_count() const { return x_bins * y_bins; }
    double x_edge(int i) const { return x_min + (x_max - x_min) * i / x_bins; }
    double y_edge(int j) const { return y_min + (y_max - y_min) * j / y_bins; }

    // The bin holding p (the upper edges belong to the last bins), or -1 if p is outside the
    // grid or not a number.
    int bin_of(GridPoint p) const {
        if (!(p.x >= x_min && p.x <= x_max && p.y >= y_min && p.y <= y_max)) return -1;
        const int i = std::min(int((p.x - x_min) / (x_max - x_min) * x_bins), x_bins - 1);
        const int j = std::min(int((p.y - y_min) / (y_max - y_min) * y_bins), y_bins - 1);
        return j * x_bins + i;
    }

    std::string describe_bin(int bin) const {
        const int i = bin % x_bins, j = bin / x_bins;
        std::ostringstream s;
        s << "bin (" << i << ", " << j << ") = [" << x_edge(i) << ", " << x_edge(i + 1) << "] x ["
          << y_edge(j) << ", " << y_edge(j + 1) << "]";
        return s.str();
    }
};

// The density integrated over each bin: integral(x0, x1, y0, y1) for each bin in grid order.
template <class BinIntegral>
std::vector<double> bin_probabilities(const ChiSquareGrid& grid, const BinIntegral& integral) {
    std::vector<double> p(grid.bin_count());
    for (int j = 0; j < grid.y_bins; ++j) {
        for (int i = 0; i < grid.x_bins; ++i) {
            p[j * grid.x_bins + i] =
                integral(grid.x_edge(i), grid.x_edge(i + 1), grid.y_edge(j), grid.y_edge(j + 1));
        }
    }
    return p;
}

// Bin probabilities of a smooth density(x, y) (per unit area of the parameterisation).
template <class Density>
std::vector<double> bin_probabilities_simpson(const ChiSquareGrid& grid, const Density& density,
                                              double tolerance = 1e-10) {
    return bin_probabilities(grid, [&](double x0, double x1, double y0, double y1) {
        return adaptive_simpson_2d(density, x0, x1, y0, y1, tolerance);
    });
}

// Bin probabilities of a density with edges inside bins, by n x n midpoint sums per bin.
template <class Density>
std::vector<double> bin_probabilities_midpoint(const ChiSquareGrid& grid, const Density& density,
                                               int n = 64) {
    return bin_probabilities(grid, [&](double x0, double x1, double y0, double y1) {
        return midpoint_2d(density, x0, x1, y0, y1, n);
    });
}

struct ChiSquareResult {
    double statistic = 0;
    int dof = 0;
    // 0 when the test failed outright: a sample outside the grid or NaN, a sample in a bin of
    // zero probability, or a density that does not integrate to 1 over the grid.
    double p_value = 0;
    // What was tested and, on failure, why: for EXPECT_GT(r.p_value, alpha) << r.description.
    std::string description;
};

// Pearson's test of `counts` (samples per bin) against `probabilities` (the density's mass per
// bin) for sample_count samples. Bins expecting fewer than 5 samples are pooled into one cell
// (grown with the next smallest bins until it expects 5), so that the statistic is close to its
// chi-square distribution; dof = cells - 1.
inline ChiSquareResult chi_square_statistic(const ChiSquareGrid& grid,
                                            const std::vector<double>& counts,
                                            const std::vector<double>& probabilities,
                                            std::uint64_t sample_count) {
    constexpr double kMinExpected = 5;
    ChiSquareResult result;
    std::ostringstream s;
    double mass = 0;
    for (double p : probabilities) mass += p;
    s << sample_count << " samples in " << grid.x_bins << " x " << grid.y_bins
      << " bins; the density integrates to " << mass << " over the grid";
    const auto fail = [&](const std::string& why) {
        result.statistic = std::numeric_limits<double>::infinity();
        result.p_value = 0;
        result.description = s.str() + "; FAILED: " + why;
        return result;
    };
    if (std::abs(mass - 1) > 1e-3) return fail("the density does not integrate to 1");

    struct Cell {
        double expected, observed;
        int bin;
    };
    std::vector<Cell> cells;
    for (int b = 0; b < grid.bin_count(); ++b) {
        const double expected = probabilities[b] * double(sample_count);
        if (probabilities[b] <= 0 && counts[b] > 0) {
            std::ostringstream why;
            why << counts[b] << " samples in " << grid.describe_bin(b) << " where the density is 0";
            return fail(why.str());
        }
        cells.push_back({expected, counts[b], b});
    }
    std::sort(cells.begin(), cells.end(),
              [](const Cell& a, const Cell& b) { return a.expected < b.expected; });

    Cell pool{0, 0, -1};
    int pooled_bins = 0;
    std::size_t next = 0;
    while (next < cells.size() && (cells[next].expected < kMinExpected ||
                                   (pooled_bins > 0 && pool.expected < kMinExpected))) {
        pool.expected += cells[next].expected;
        pool.observed += cells[next].observed;
        ++pooled_bins;
        ++next;
    }
    double statistic = 0, worst_term = -1;
    int cell_count = 0;
    Cell worst{0, 0, -1};
    const auto add = [&](const Cell& c) {
        if (c.expected <= 0) return;
        const double term = (c.observed - c.expected) * (c.observed - c.expected) / c.expected;
        statistic += term;
        ++cell_count;
        if (term > worst_term) {
            worst_term = term;
            worst = c;
        }
    };
    for (std::size_t k = next; k < cells.size(); ++k) add(cells[k]);
    if (pooled_bins > 0) add(pool);

    result.statistic = statistic;
    result.dof = std::max(cell_count - 1, 0);
    result.p_value = result.dof > 0 ? chi_square_p_value(statistic, result.dof) : 1;
    s << "; " << pooled_bins << " bins expecting < " << kMinExpected << " samples pooled into "
      << (pooled_bins > 0 ? 1 : 0) << " cell; chi-square " << statistic << " on " << result.dof
      << " degrees of freedom, p = " << result.p_value;
    if (worst_term >= 0) {
        s << "; largest term " << worst_term << " from "
          << (worst.bin >= 0 ? grid.describe_bin(worst.bin) : "the pooled cell") << ": observed "
          << worst.observed << ", expected " << worst.expected;
    }
    result.description = s.str();
    return result;
}

// Draws sample_count points from generate(i), i = 0, 1, ..., counts them into the grid and
// tests them against `probabilities` (from bin_probabilities*). A point outside the grid or
// with a NaN coordinate fails the test at once.
template <class Generator>
ChiSquareResult chi_square_test(const ChiSquareGrid& grid, const std::vector<double>& probabilities,
                                std::uint64_t sample_count, const Generator& generate) {
    std::vector<double> counts(grid.bin_count(), 0.0);
    for (std::uint64_t i = 0; i < sample_count; ++i) {
        const GridPoint p = generate(i);
        const int bin = grid.bin_of(p);
        if (bin < 0) {
            std::ostringstream s;
            s << "sample " << i << " at (" << p.x << ", " << p.y << ") lies outside the grid ["
              << grid.x_min << ", " << grid.x_max << "] x [" << grid.y_min << ", " << grid.y_max
              << "]";
            ChiSquareResult r;
            r.statistic = std::numeric_limits<double>::infinity();
            r.description = "FAILED: " + s.str();
            return r;
        }
        counts[bin] += 1;
    }
    return chi_square_statistic(grid, counts, probabilities, sample_count);
}

}  // namespace glint
