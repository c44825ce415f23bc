// Interval arithmetic over the reals (Moore 1966), in double precision and rounded outwards:
// each operation returns an interval that contains f(a, b) for every a and b in its arguments.
// The implicit-surface solver uses it to prove that a piece of a ray holds no root.
#pragma once

#include <limits>

namespace glint {

// [lo, hi]. Endpoints may be infinite. The empty interval (lo > hi) means "no real value": the
// result of sqrt or log wholly outside their domain, or of x/0. Operations on an empty interval
// give the empty interval. A function that is undefined for part of its argument returns its
// range over the part where it is defined (the "containment set" convention of IEEE 1788).
// Invariant of every result that is not empty: lo < +inf, hi > -inf, no NaN.
struct RealInterval {
    double lo = 0, hi = 0;

    static constexpr RealInterval point(double x) { return {x, x}; }
    static constexpr RealInterval empty() {
        return {std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
    }
    static constexpr RealInterval whole() {
        return {-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    }

    constexpr bool is_empty() const { return !(lo <= hi); }
    constexpr bool contains(double x) const { return lo <= x && x <= hi; }
    // True when every element is > 0 or every element is < 0 (and when empty).
    constexpr bool excludes_zero() const { return !(lo <= 0 && 0 <= hi); }
    constexpr double width() const { return hi - lo; }
    constexpr double magnitude() const {  // max |x|
        return (-lo > hi) ? -lo : hi;
    }
    constexpr bool operator==(const RealInterval&) const = default;
};

// The smallest interval holding both; the intersection (maybe empty).
RealInterval hull(RealInterval a, RealInterval b);
RealInterval intersect(RealInterval a, RealInterval b);

RealInterval operator-(RealInterval a);
RealInterval operator+(RealInterval a, RealInterval b);
RealInterval operator-(RealInterval a, RealInterval b);
// Products of endpoints take 0 * inf = 0: endpoints are limits, and the product of a number
// near 0 and a large one is anything between, which the other endpoint products bound.
RealInterval operator*(RealInterval a, RealInterval b);
// Division by an interval that contains 0 gives the hull of the two half-lines (or the whole
// line); by [0, 0] the empty interval.
RealInterval operator/(RealInterval a, RealInterval b);

// a^n for an integer n, tight for even n (the result is >= 0) and odd n (monotonic);
// n < 0 is 1 / a^-n; a^0 = 1.
RealInterval pow(RealInterval a, int n);
// a^p for a real p that is not an integer: defined for a >= 0 (0^p = 0 for p > 0, +inf for
// p < 0).
RealInterval pow(RealInterval a, double p);
// a^b for interval exponents: exp(b log a) on a >= 0. When a reaches below 0 and b holds an
// integer, negative bases have real powers too, and the result is the whole line.
RealInterval pow(RealInterval a, RealInterval b);

RealInterval sqrt(RealInterval a);  // on a >= 0
RealInterval exp(RealInterval a);
RealInterval log(RealInterval a);  // on a > 0; log(0) is -inf, so [0, b] gives [-inf, log b]
RealInterval sin(RealInterval a);
RealInterval cos(RealInterval a);
RealInterval abs(RealInterval a);
// The whole numbers below (floor) or towards 0 (trunc) of the interval's points: steps, so
// continuous only where the interval holds no step (floor(lo) = floor(hi)).
RealInterval floor(RealInterval a);
RealInterval trunc(RealInterval a);
RealInterval min(RealInterval a, RealInterval b);
RealInterval max(RealInterval a, RealInterval b);
// The angle of the points (x, y), in [-pi, pi] with the cut along the negative x axis: from the
// box's corners where the box keeps clear of the origin and the cut, else the whole [-pi, pi].
RealInterval atan2(RealInterval y, RealInterval x);
// Whether atan2 is continuous over the box: it holds neither the origin nor a point of the cut
// (x <= 0, y = 0), where the angle jumps from pi to -pi.
bool atan2_continuous(RealInterval y, RealInterval x);

}  // namespace glint
