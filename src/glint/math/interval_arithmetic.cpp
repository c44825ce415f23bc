// Interval arithmetic with outward rounding. Every inexact endpoint is pushed outwards by at
// least two units in the last place, which covers the error of the correctly rounded basic
// operations (half an ulp) and of glibc's exp, log, sin, cos and pow (under one ulp).
#include "glint/math/interval_arithmetic.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace glint {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kMax = std::numeric_limits<double>::max();
constexpr double kTiny = std::numeric_limits<double>::denorm_min();

// |x| * 2^-51 is at least two ulps of x; the subtraction itself rounds by at most half of one
// ulp, so the result lies at least 1.5 ulps below x. kTiny handles zero and subnormals.
// +inf as a lower bound (an overflowed lower endpoint) becomes the largest finite double.
inline double down(double x) {
    const double r = x - (std::abs(x) * 0x1p-51 + kTiny);
    return r == r ? r : kMax;
}
inline double up(double x) {
    const double r = x + (std::abs(x) * 0x1p-51 + kTiny);
    return r == r ? r : -kMax;
}
inline RealInterval outward(double lo, double hi) { return {down(lo), up(hi)}; }

// Endpoint product with 0 * inf = 0 (see operator*).
inline double times(double a, double b) { return (a == 0 || b == 0) ? 0.0 : a * b; }

// Whether [lo, hi] holds an angle phase + 2 k pi. Generous by a relative margin: including an
// extremum that lies just outside only widens the result, which stays conservative.
bool holds_angle(double lo, double hi, double phase) {
    constexpr double two_pi = 2 * std::numbers::pi;
    const double margin = 1e-12 * (1 + std::abs(lo) + std::abs(hi));
    const double k = std::ceil((lo - margin - phase) / two_pi);
    return phase + k * two_pi <= hi + margin;
}

// sin or cos over [lo, hi] from their values at the ends and the extrema inside.
RealInterval periodic(RealInterval a, double (*f)(double), double max_phase, double min_phase) {
    if (a.is_empty()) return RealInterval::empty();
    // Beyond 2^50 consecutive doubles are further apart than a period: no reduction is
    // meaningful, and the interval of any width covers a full period anyway.
    if (!(a.hi - a.lo < 2 * std::numbers::pi) || std::abs(a.lo) > 0x1p50 ||
        std::abs(a.hi) > 0x1p50) {
        return {-1, 1};
    }
    const double f_lo = f(a.lo), f_hi = f(a.hi);
    double lo = down(std::min(f_lo, f_hi)), hi = up(std::max(f_lo, f_hi));
    if (holds_angle(a.lo, a.hi, max_phase)) hi = 1;
    if (holds_angle(a.lo, a.hi, min_phase)) lo = -1;
    return {std::max(lo, -1.0), std::min(hi, 1.0)};
}

// Lower and upper bounds of x^n for x >= 0, n >= 1. Square-and-multiply with every product
// rounded down (or up): products of non-negative numbers grow with their factors, so rounding
// each step one way keeps a bound. Cheaper than pow, which it replaces for n <= 64.
RealInterval power_bounds(double x, unsigned n) {
    if (n > 64) return outward(std::pow(x, double(n)), std::pow(x, double(n)));
    double lo = 1, hi = 1, base_lo = x, base_hi = x;
    for (;;) {
        if (n & 1) {
            lo = down(lo * base_lo);
            hi = up(hi * base_hi);
        }
        n >>= 1;
        if (n == 0) break;
        base_lo = down(base_lo * base_lo);
        base_hi = up(base_hi * base_hi);
    }
    return {std::max(lo, 0.0), hi};
}

double sin_of(double x) { return std::sin(x); }
double cos_of(double x) { return std::cos(x); }

}  // namespace

RealInterval hull(RealInterval a, RealInterval b) {
    if (a.is_empty()) return b;
    if (b.is_empty()) return a;
    return {std::min(a.lo, b.lo), std::max(a.hi, b.hi)};
}

RealInterval intersect(RealInterval a, RealInterval b) {
    if (a.is_empty() || b.is_empty()) return RealInterval::empty();
    const RealInterval r{std::max(a.lo, b.lo), std::min(a.hi, b.hi)};
    return r.is_empty() ? RealInterval::empty() : r;
}

RealInterval operator-(RealInterval a) {
    if (a.is_empty()) return a;
    return {-a.hi, -a.lo};
}

RealInterval operator+(RealInterval a, RealInterval b) {
    if (a.is_empty() || b.is_empty()) return RealInterval::empty();
    return outward(a.lo + b.lo, a.hi + b.hi);
}

RealInterval operator-(RealInterval a, RealInterval b) {
    if (a.is_empty() || b.is_empty()) return RealInterval::empty();
    return outward(a.lo - b.hi, a.hi - b.lo);
}

RealInterval operator*(RealInterval a, RealInterval b) {
    if (a.is_empty() || b.is_empty()) return RealInterval::empty();
    const double p1 = times(a.lo, b.lo), p2 = times(a.lo, b.hi);
    const double p3 = times(a.hi, b.lo), p4 = times(a.hi, b.hi);
    return outward(std::min({p1, p2, p3, p4}), std::max({p1, p2, p3, p4}));
}

RealInterval operator/(RealInterval a, RealInterval b) {
    if (a.is_empty() || b.is_empty()) return RealInterval::empty();
    RealInterval reciprocal;
    if (b.lo > 0 || b.hi < 0) {
        reciprocal = outward(1 / b.hi, 1 / b.lo);
    } else if (b.lo == 0 && b.hi == 0) {
        return RealInterval::empty();
    } else if (b.lo == 0) {
        reciprocal = {down(1 / b.hi), kInf};
    } else if (b.hi == 0) {
        reciprocal = {-kInf, up(1 / b.lo)};
    } else {
        return RealInterval::whole();
    }
    return a * reciprocal;
}

RealInterval pow(RealInterval a, int n) {
    if (a.is_empty()) return a;
    if (n == 0) return {1, 1};
    if (n < 0) {
        // 1 / a^|n|, with |n| taken without overflow for the most negative int.
        const RealInterval positive = n == std::numeric_limits<int>::min()
                                          ? pow(a, std::numeric_limits<int>::max()) * a
                                          : pow(a, -n);
        return RealInterval{1, 1} / positive;
    }
    if (n == 1) return a;
    // Bounds of |x|^n for the endpoints; x^n takes the sign of x for odd n.
    const auto lower = [n](double x) { return power_bounds(std::abs(x), unsigned(n)).lo; };
    const auto upper = [n](double x) { return power_bounds(std::abs(x), unsigned(n)).hi; };
    if (n % 2 == 1) {  // monotonic
        return {a.lo < 0 ? -upper(a.lo) : lower(a.lo), a.hi < 0 ? -lower(a.hi) : upper(a.hi)};
    }
    if (a.lo >= 0) return {lower(a.lo), upper(a.hi)};
    if (a.hi <= 0) return {lower(a.hi), upper(a.lo)};
    return {0, upper(a.magnitude())};  // even power of an interval around 0
}

RealInterval pow(RealInterval a, double p) {
    const RealInterval base = intersect(a, {0, kInf});
    if (base.is_empty()) return base;
    if (p > 0) return {std::max(0.0, down(std::pow(base.lo, p))), up(std::pow(base.hi, p))};
    return {std::max(0.0, down(std::pow(base.hi, p))), up(std::pow(base.lo, p))};
}

RealInterval pow(RealInterval a, RealInterval b) {
    if (a.is_empty() || b.is_empty()) return RealInterval::empty();
    if (b.lo == b.hi) {
        const double p = b.lo;
        if (p == std::nearbyint(p) && std::abs(p) <= 1 << 30) return pow(a, int(p));
        return pow(a, p);
    }
    // Negative bases have real powers exactly at integer exponents: nothing tight to say.
    if (a.lo < 0 && std::floor(b.hi) >= b.lo) return RealInterval::whole();
    const RealInterval base = intersect(a, {0, kInf});
    if (base.is_empty()) return base;
    if (base.hi == 0) return b.lo > 0 ? RealInterval{0, 0} : RealInterval{0, kInf};  // 0^b
    // log(0) = -inf makes b * log(base) reach +-inf, and exp maps those to 0 and +inf: the
    // limits of 0^b for b > 0 and b < 0. 0^0 = 1 lies between them.
    return exp(b * log(base));
}

RealInterval sqrt(RealInterval a) {
    if (a.is_empty() || a.hi < 0) return RealInterval::empty();
    return {a.lo <= 0 ? 0.0 : std::max(0.0, down(std::sqrt(a.lo))), up(std::sqrt(a.hi))};
}

RealInterval exp(RealInterval a) {
    if (a.is_empty()) return a;
    return {std::max(0.0, down(std::exp(a.lo))), up(std::exp(a.hi))};
}

RealInterval log(RealInterval a) {
    if (a.is_empty() || a.hi <= 0) return RealInterval::empty();
    return {a.lo <= 0 ? -kInf : down(std::log(a.lo)), up(std::log(a.hi))};
}

RealInterval sin(RealInterval a) {
    return periodic(a, sin_of, std::numbers::pi / 2, -std::numbers::pi / 2);
}

RealInterval cos(RealInterval a) { return periodic(a, cos_of, 0, std::numbers::pi); }

RealInterval abs(RealInterval a) {
    if (a.is_empty()) return a;
    if (a.lo >= 0) return a;
    if (a.hi <= 0) return -a;
    return {0, a.magnitude()};
}

RealInterval floor(RealInterval a) {
    if (a.is_empty()) return a;
    return {std::floor(a.lo), std::floor(a.hi)};
}

RealInterval trunc(RealInterval a) {
    if (a.is_empty()) return a;
    return {std::trunc(a.lo), std::trunc(a.hi)};
}

RealInterval min(RealInterval a, RealInterval b) {
    if (a.is_empty() || b.is_empty()) return RealInterval::empty();
    return {std::min(a.lo, b.lo), std::min(a.hi, b.hi)};
}

RealInterval max(RealInterval a, RealInterval b) {
    if (a.is_empty() || b.is_empty()) return RealInterval::empty();
    return {std::max(a.lo, b.lo), std::max(a.hi, b.hi)};
}

bool atan2_continuous(RealInterval y, RealInterval x) {
    return !(x.lo <= 0 && y.lo <= 0 && y.hi >= 0);
}

RealInterval atan2(RealInterval y, RealInterval x) {
    if (y.is_empty() || x.is_empty()) return RealInterval::empty();
    constexpr double pi = std::numbers::pi;
    if (!atan2_continuous(y, x)) return outward(-pi, pi);
    // A convex set clear of the origin and the cut: its angles form an interval whose ends are
    // the angles of extreme points, the box's corners (infinite ones as limits).
    double lo = kInf, hi = -kInf;
    for (const double yc : {y.lo, y.hi})
        for (const double xc : {x.lo, x.hi}) {
            const double a = std::atan2(yc, xc);
            lo = std::min(lo, a);
            hi = std::max(hi, a);
        }
    return {std::max(down(lo), -pi - 1e-15), std::min(up(hi), pi + 1e-15)};
}

}  // namespace glint
