// Real roots of cubic and quartic polynomials in double precision: the torus and other
// fourth-order surfaces need them. Each root is isolated between critical points and polished
// with bracketed Newton steps on the polynomial itself, so it is as accurate as its conditioning
// allows, without the cancellation of the closed forms (Cardano, Ferrari).
#pragma once

#include <array>

namespace glint {

// Up to N real roots in ascending order; `values[0, count)` hold them.
template <int N>
struct RealRoots {
    std::array<double, N> values{};
    int count = 0;

    constexpr const double* begin() const { return values.data(); }
    constexpr const double* end() const { return values.data() + count; }
    constexpr double operator[](int i) const { return values[i]; }
    constexpr bool empty() const { return count == 0; }
};

using CubicRoots = RealRoots<3>;
using QuarticRoots = RealRoots<4>;

// Real roots of a t^3 + b t^2 + c t + d = 0.
// Real roots of a t^4 + b t^3 + c t^2 + d t + e = 0.
//
// Contract of both:
// - A root where the polynomial touches zero without crossing it (a double root, to within the
//   rounding of its evaluation) is listed twice, so that a ray's entries and exits stay paired.
//   A root of odd multiplicity (a triple root) is listed once.
// - A zero leading coefficient gives the roots of the lower degree polynomial (down to linear);
//   a tiny one just gives a huge root, found like the others. All coefficients zero, or a
//   non-finite one, gives no roots.
// - Accuracy: each root is Newton-polished on the given coefficients until the polynomial's value
//   is within its rounding error bound (Higham, "Accuracy and Stability of Numerical
//   Algorithms", 5.1), i.e. backward stable. A simple root is then accurate to about 1e-16 times
//   its condition number; a double root to about 1e-8 relative.
// Allocates nothing and throws nothing; cost is a few dozen polynomial evaluations.
CubicRoots solve_cubic(double a, double b, double c, double d);
QuarticRoots solve_quartic(double a, double b, double c, double d, double e);

}  // namespace glint
