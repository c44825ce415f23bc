// Real roots of a*t^2 + b*t + c = 0, computed without catastrophic cancellation.
#pragma once

#include <optional>

namespace glint {

struct QuadraticRoots {
    float t0;  // t0 <= t1
    float t1;
};

struct QuadraticRootsDouble {
    double t0;  // t0 <= t1
    double t1;
};

// Uses the stable pair q = -(b + sign(b) sqrt(b^2 - 4ac)) / 2, t = q/a and c/q
// (Press et al., Numerical Recipes, 5.6), in double precision. A linear equation (a == 0)
// gives its single root twice. No real roots, or a == b == 0, gives nothing.
std::optional<QuadraticRoots> solve_quadratic(float a, float b, float c);
// The same for coefficients computed in double: no rounding to float on the way in or out.
std::optional<QuadraticRootsDouble> solve_quadratic_double(double a, double b, double c);

}  // namespace glint
