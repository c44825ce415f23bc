// Safeguarded Newton's method for a bracketed root: Newton steps while they stay inside the
// bracket and shrink it fast enough, bisection otherwise (rtsafe; Press et al., Numerical
// Recipes, 3rd ed., 9.4). Converges whenever the bracket holds a sign change of a continuous f.
#pragma once

#include <cmath>
#include <utility>

namespace glint {

struct NewtonResult {
    double x = 0;
    int evaluations = 0;     // calls of f beyond the bracket's ends
    bool converged = false;  // the last step was below x_tolerance (or f(x) == 0)
};

// A root of f in [x_lo, x_hi], given f_lo = f(x_lo) and f_hi = f(x_hi) of opposite signs (or
// one of them 0). f(x) returns {value, slope} (anything with those members). The iterates stay
// inside the bracket, which shrinks each step. Stops when a step is below x_tolerance, when
// f(x) == 0, or after max_evaluations; a NaN value of f stops at the current iterate,
// unconverged.
template <typename F>
NewtonResult safeguarded_newton(F&& f, double x_lo, double x_hi, double f_lo, double f_hi,
                                double x_tolerance, int max_evaluations = 100) {
    if (f_lo == 0) return {x_lo, 0, true};
    if (f_hi == 0) return {x_hi, 0, true};
    // Orient the bracket so that f(negative) < 0 < f(positive).
    double negative = x_lo, positive = x_hi;
    if (f_lo > 0) std::swap(negative, positive);
    double x = 0.5 * (x_lo + x_hi);
    double step_before = std::abs(x_hi - x_lo), step = step_before;
    NewtonResult result{x, 1, false};
    auto sample = f(x);
    // Unlike the book, the midpoint's sample shrinks the bracket too: one bisection saved.
    if (sample.value == sample.value) (sample.value < 0 ? negative : positive) = x;
    for (;;) {
        const double value = sample.value, slope = sample.slope;
        if (value != value) return result;  // NaN: f is undefined here; nothing better to say
        if (value == 0) {
            result.converged = true;
            return result;
        }
        // Bisect when the Newton step would leave the bracket, or would not halve the step of
        // two iterations ago (slow convergence), or the slope is useless.
        const bool outside =
            ((x - positive) * slope - value) * ((x - negative) * slope - value) > 0;
        const bool slow = std::abs(2 * value) > std::abs(step_before * slope);
        if (outside || slow || !std::isfinite(slope) || slope == 0) {
            step_before = step;
            step = 0.5 * (positive - negative);
            x = negative + step;
        } else {
            step_before = step;
            step = value / slope;
            x -= step;
        }
        result.x = x;
        if (std::abs(step) < x_tolerance || result.evaluations >= max_evaluations) {
            result.converged = std::abs(step) < x_tolerance;
            return result;
        }
        sample = f(x);
        ++result.evaluations;
        (sample.value < 0 ? negative : positive) = x;
    }
}

}  // namespace glint
