// The quadratic formula in double, taking the root without cancellation first and the other from
// the product of the roots (Numerical Recipes 5.6).
#include "glint/math/quadratic.h"

#include <cmath>
#include <utility>

namespace glint {

std::optional<QuadraticRoots> solve_quadratic(float a, float b, float c) {
    const double da = a, db = b, dc = c;
    if (da == 0) {
        if (db == 0) return std::nullopt;
        const auto t = static_cast<float>(-dc / db);
        return QuadraticRoots{t, t};
    }
    const double discriminant = db * db - 4 * da * dc;
    if (discriminant < 0) return std::nullopt;
    const double root = std::sqrt(discriminant);
    const double q = db < 0 ? -0.5 * (db - root) : -0.5 * (db + root);
    double t0 = q / da;
    // q == 0 only when b == 0 and c == 0: both roots are zero.
    double t1 = q != 0 ? dc / q : 0.0;
    if (t0 > t1) std::swap(t0, t1);
    return QuadraticRoots{static_cast<float>(t0), static_cast<float>(t1)};
}

}  // namespace glint
