// The quadratic formula in double, taking the root without cancellation first and the other from
// the product of the roots (Numerical Recipes 5.6).
#include "glint/math/quadratic.h"

#include <cmath>
#include <utility>

namespace glint {

std::optional<QuadraticRootsDouble> solve_quadratic_double(double a, double b, double c) {
    if (a == 0) {
        if (b == 0) return std::nullopt;
        const double t = -c / b;
        return QuadraticRootsDouble{t, t};
    }
    const double discriminant = b * b - 4 * a * c;
    if (discriminant < 0) return std::nullopt;
    const double root = std::sqrt(discriminant);
    const double q = b < 0 ? -0.5 * (b - root) : -0.5 * (b + root);
    double t0 = q / a;
    // q == 0 only when b == 0 and c == 0: both roots are zero.
    double t1 = q != 0 ? c / q : 0.0;
    if (t0 > t1) std::swap(t0, t1);
    return QuadraticRootsDouble{t0, t1};
}

std::optional<QuadraticRoots> solve_quadratic(float a, float b, float c) {
    const auto roots = solve_quadratic_double(double{a}, double{b}, double{c});
    if (!roots) return std::nullopt;
    return QuadraticRoots{static_cast<float>(roots->t0), static_cast<float>(roots->t1)};
}

}  // namespace glint
