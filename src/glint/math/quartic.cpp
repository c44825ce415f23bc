// Root isolation by critical points (as in Yuksel 2022, "High-Performance Polynomial Root Finding
// for Graphics"): between two consecutive roots of p' the polynomial p is monotone, so it has a
// root there exactly when its values at the two ends differ in sign, and a Newton iteration kept
// inside that bracket finds it. The critical points come from the same method one degree lower.
#include "glint/math/quartic.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace glint {

namespace {

constexpr double kUnitRoundoff = std::numeric_limits<double>::epsilon() / 2;

// c[0] t^n + c[1] t^(n-1) + ... + c[n], highest degree first.
template <int Degree>
using Coefficients = std::array<double, Degree + 1>;

struct Evaluation {
    double value;
    double derivative;
    double error;  // a bound on how far `value` may be from zero at a root, from rounding alone
};

// Horner's rule with its running error bound |computed - exact| <= gamma_2n sum |c_i| |x|^i,
// gamma_2n ~= 2n u (Higham, "Accuracy and Stability of Numerical Algorithms", 5.1). Twice that
// also covers coefficients that were themselves rounded when the caller computed them.
template <int Degree>
Evaluation evaluate(const Coefficients<Degree>& c, double x) {
    double p = c[0], dp = 0, magnitude = std::abs(c[0]);
    const double ax = std::abs(x);
    for (int i = 1; i <= Degree; ++i) {
        dp = dp * x + p;
        p = p * x + c[i];
        magnitude = magnitude * ax + std::abs(c[i]);
    }
    return {p, dp, 4 * Degree * kUnitRoundoff * magnitude};
}

// Fujiwara's bound (1916): every complex root z has |z| <= 2 max_i |c_i / c_0|^(1/i), with the
// constant term halved. Infinite when the ratios overflow, i.e. c[0] is negligible. The i-th
// root is only taken when ratio_i exceeds the running maximum to the i-th power.
template <int Degree>
double root_bound(const Coefficients<Degree>& c) {
    double bound = 0, power = 1;  // power = bound^i
    for (int i = 1; i <= Degree; ++i) {
        power *= bound;
        const double ratio = std::abs(c[i] / c[0]) / (i == Degree ? 2 : 1);
        if (!(ratio > power)) continue;
        bound = i == 1   ? ratio
                : i == 2 ? std::sqrt(ratio)
                : i == 3 ? std::cbrt(ratio)
                         : std::sqrt(std::sqrt(ratio));
        power = ratio;
    }
    // The margin keeps a root that lies on the bound strictly inside; a zero bound (p = c0 t^n)
    // still needs an interval around its root at 0.
    return bound > 0 ? 2.02 * bound : 1.0;
}

// The root of p in [lo, hi], where p(lo) and p(hi) have opposite signs (`rising`: p(lo) < 0).
// Newton steps while they stay in the bracket and shrink at least as fast as bisection would,
// bisection otherwise (rtsafe, Numerical Recipes 9.4). Stops once the value is within its
// rounding error or the steps are down to an ulp.
template <int Degree>
double root_in_bracket(const Coefficients<Degree>& c, double lo, double hi, bool rising) {
    double x = lo + 0.5 * (hi - lo);
    double last_step = hi - lo;
    for (int iteration = 0; iteration < 200; ++iteration) {
        const Evaluation e = evaluate<Degree>(c, x);
        if (e.value == 0) return x;
        if ((e.value < 0) == rising) {
            lo = x;
        } else {
            hi = x;
        }
        double next = x - e.value / e.derivative;
        // Within rounding of zero the sign says little more; one last Newton step still removes
        // the error that the bound allowed (quadratic convergence) down to the real noise.
        if (std::abs(e.value) <= e.error) return next >= lo && next <= hi ? next : x;
        // The negated test also sends a NaN step (zero derivative) to bisection.
        if (!(next > lo && next < hi && std::abs(next - x) <= 0.5 * last_step)) {
            next = lo + 0.5 * (hi - lo);
        }
        last_step = std::abs(next - x);
        if (last_step <= 2 * kUnitRoundoff * std::abs(next)) return next;
        x = next;
    }
    return x;
}

template <int From, int To>
RealRoots<To> widen(const RealRoots<From>& r) {
    RealRoots<To> out;
    for (double t : r) out.values[out.count++] = t;
    return out;
}

template <int Degree>
RealRoots<Degree> solve(const Coefficients<Degree>& c);

template <>
RealRoots<1> solve<1>(const Coefficients<1>& c) {
    RealRoots<1> r;
    if (c[0] != 0) r.values[r.count++] = -c[1] / c[0];
    return r;
}

template <int Degree>
Coefficients<Degree - 1> without_leading(const Coefficients<Degree>& c) {
    Coefficients<Degree - 1> lower;
    std::copy(c.begin() + 1, c.end(), lower.begin());
    return lower;
}

// Roots of p' in ascending order; c[0] != 0.
template <int Degree>
RealRoots<Degree - 1> critical_points(const Coefficients<Degree>& c) {
    RealRoots<Degree - 1> r;
    if constexpr (Degree == 2) {
        r.values[r.count++] = -c[1] / (2 * c[0]);
    } else if constexpr (Degree == 3) {
        // p' = 3 c0 t^2 + 2 c1 t + c2 with the cancellation-free pair q / a, c / q (Numerical
        // Recipes 5.6). A double critical point may come out as two close ones or none: either
        // way the sign test below sees the same thing.
        const double a = 3 * c[0], b = 2 * c[1], cc = c[2];
        const double discriminant = b * b - 4 * a * cc;
        if (discriminant < 0) return r;
        const double q = -0.5 * (b + std::copysign(std::sqrt(discriminant), b));
        double t0 = q / a, t1 = q != 0 ? cc / q : 0.0;
        if (t0 > t1) std::swap(t0, t1);
        r.values = {t0, t1};
        r.count = 2;
    } else {
        Coefficients<Degree - 1> derivative;
        for (int i = 0; i < Degree; ++i) derivative[i] = (Degree - i) * c[i];
        r = solve<Degree - 1>(derivative);
    }
    return r;
}

template <int Degree>
RealRoots<Degree> solve(const Coefficients<Degree>& c) {
    // A zero (or negligible) leading coefficient: the polynomial is of lower degree.
    const double bound =
        c[0] != 0 ? root_bound<Degree>(c) : std::numeric_limits<double>::infinity();
    if (!std::isfinite(bound)) {
        return widen<Degree - 1, Degree>(solve<Degree - 1>(without_leading<Degree>(c)));
    }

    // The points -bound, the critical points and +bound cut the line into monotone pieces.
    constexpr int kMaxPoints = Degree + 1;
    std::array<double, kMaxPoints> x{};
    std::array<double, kMaxPoints> value{};
    std::array<bool, kMaxPoints> zero{};
    int n = 0;
    x[n++] = -bound;
    for (double t : critical_points<Degree>(c)) x[n++] = std::clamp(t, -bound, bound);
    x[n++] = bound;
    for (int i = 0; i < n; ++i) {
        const Evaluation e = evaluate<Degree>(c, x[i]);
        value[i] = e.value;
        // A critical point where p vanishes to rounding is a root where p touches zero.
        zero[i] = i > 0 && i < n - 1 && std::abs(e.value) <= e.error;
    }

    RealRoots<Degree> roots;
    const auto add = [&roots](double t) {
        // More than Degree only when p is zero to rounding almost everywhere: keep the first.
        if (roots.count < Degree) roots.values[roots.count++] = t;
    };
    // Invariant: point i is not a zero point (the ends never are), so value[i] has a sign.
    for (int i = 0; i < n - 1;) {
        if (!zero[i + 1]) {
            if ((value[i] > 0) != (value[i + 1] > 0)) {
                add(root_in_bracket<Degree>(c, x[i], x[i + 1], value[i] < 0));
            }
            ++i;
            continue;
        }
        // A run of zero points (a double critical point may come out as two) is one root: the
        // one nearest zero. It is listed twice when p keeps its sign across it (touches zero).
        int j = i + 1, best = i + 1;
        for (; zero[j]; ++j) {
            if (std::abs(value[j]) < std::abs(value[best])) best = j;
        }
        add(x[best]);
        if ((value[i] > 0) == (value[j] > 0)) add(x[best]);
        i = j;
    }
    return roots;
}

// The coefficients scaled by a power of two (exact, so the roots and the rounding are unchanged)
// to put the largest near 1, away from overflow and underflow in evaluation. False when one is
// not finite, or all are zero.
template <std::size_t N>
bool normalize(std::array<double, N>& c) {
    double largest = 0;
    for (double x : c) {
        if (!std::isfinite(x)) return false;
        largest = std::max(largest, std::abs(x));
    }
    if (largest == 0) return false;
    int exponent = 0;
    std::frexp(largest, &exponent);
    const double scale = std::ldexp(1.0, -exponent);
    for (double& x : c) x *= scale;
    return true;
}

}  // namespace

CubicRoots solve_cubic(double a, double b, double c, double d) {
    Coefficients<3> coefficients{a, b, c, d};
    if (!normalize(coefficients)) return {};
    return solve<3>(coefficients);
}

QuarticRoots solve_quartic(double a, double b, double c, double d, double e) {
    Coefficients<4> coefficients{a, b, c, d, e};
    if (!normalize(coefficients)) return {};
    return solve<4>(coefficients);
}

}  // namespace glint
