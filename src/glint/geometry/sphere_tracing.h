// Sphere tracing (Hart 1996, "Sphere tracing: a geometric method for the antialiased ray
// tracing of implicit surfaces"): step along the ray by a lower bound of the distance to the
// surface until it falls below epsilon; and, for rays that start inside, a march to the exit.
// Shared by the distance-estimated fractals.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "glint/math/interval.h"
#include "glint/math/ray.h"
#include "glint/math/vector.h"

namespace glint {

struct SphereTraceSettings {
    Point3 center;        // of the bounding sphere, outside which there is no surface
    double radius = 0;    // of the bounding sphere, world units
    double epsilon = 0;   // a hit is where the estimate drops below epsilon, world units
    int max_steps = 512;  // estimates evaluated per ray at most; then the ray misses
};

struct SphereTrace {
    enum class Outcome { kHit, kMiss, kStepCap };
    Outcome outcome = Outcome::kMiss;
    double t = 0;  // of the hit
    // Whether the hit is where the ray leaves the solid (it started inside) rather than enters.
    bool leaving = false;
    int steps = 0;  // estimates evaluated
};

// ShapeHit::part of a distance-estimated shape's hit where the ray leaves the solid; 0 where it
// enters. Estimated normals are noisy at the epsilon scale, so CSG asks the hit, not the normal.
inline constexpr std::uint32_t kLeavingHit = 1;

// `estimate(Point3)` returns a distance estimate in world units: a lower bound of the distance
// to the surface outside it, <= 0 inside. The solid is where estimate < epsilon, and its surface
// is found from both sides:
// - From outside, step by the estimate until it falls below epsilon: the ray enters there.
// - A ray that starts within the epsilon shell (a shadow or reflection ray leaving a hit point)
//   first walks out of it in steps of epsilon. It is heading into the solid, not out of it, if
//   the estimate is negative or falls below half its starting value on the way.
// - A ray that starts inside (estimate < 0) or heads into the solid from the shell marches to
//   where it leaves: no estimate bounds the distance to the boundary from inside, so it takes
//   even steps of at least epsilon, as many as the step budget has left for the rest of the
//   bounding sphere, and bisects the step in which the estimate first reaches epsilon again.
//   Gaps in the solid narrower than a step can be stepped over.
template <typename Estimate>
SphereTrace sphere_trace(const Estimate& estimate, const Ray& ray, Interval t_range,
                         const SphereTraceSettings& settings) {
    SphereTrace trace;
    // Clip to the bounding sphere: |o + t d - c|^2 = r^2 with |d| = 1, in double.
    const double ox = double(ray.origin.x) - settings.center.x;
    const double oy = double(ray.origin.y) - settings.center.y;
    const double oz = double(ray.origin.z) - settings.center.z;
    const double b = ox * ray.direction.x + oy * ray.direction.y + oz * ray.direction.z;
    const double c = ox * ox + oy * oy + oz * oz - settings.radius * settings.radius;
    const double discriminant = b * b - c;
    if (!(discriminant >= 0) || !(settings.epsilon > 0)) return trace;
    const double s = std::sqrt(discriminant);
    const double t_begin = std::max(double(t_range.min), -b - s);
    const double t_end = std::min(double(t_range.max), -b + s);
    if (!(t_begin <= t_end)) return trace;

    const double epsilon = settings.epsilon;
    const auto at = [&](double t) {
        return Point3(float(ray.origin.x + t * ray.direction.x),
                      float(ray.origin.y + t * ray.direction.y),
                      float(ray.origin.z + t * ray.direction.z));
    };
    const auto evaluate = [&](double t) {
        ++trace.steps;
        return estimate(at(t));
    };
    const auto hit = [&](double t, bool leaving) {
        trace.outcome = SphereTrace::Outcome::kHit;
        trace.t = t;
        trace.leaving = leaving;
        return trace;
    };
    // From t, inside the solid, to the first sample outside it; then bisection on the last step
    // to a hundredth of epsilon. The hit is the bracket's outer end, so that a ray continuing
    // from it starts outside.
    const auto march_to_exit = [&](double t) {
        const int budget = std::max(1, settings.max_steps - trace.steps);
        const double step = std::max(epsilon, (t_end - t) / budget);
        double inside = t;
        for (int k = 0; k <= budget; ++k) {
            const double next = std::min(inside + step, t_end);
            if (!(next > inside)) break;  // still inside where the range ends
            if (evaluate(next) >= epsilon) {
                double outside = next;
                while (outside - inside > 0.01 * epsilon) {
                    const double mid = 0.5 * (inside + outside);
                    if (!(mid > inside && mid < outside)) break;
                    (evaluate(mid) < epsilon ? inside : outside) = mid;
                }
                return hit(outside, true);
            }
            inside = next;
        }
        return trace;
    };

    double t = t_begin;
    double d = evaluate(t);
    const double start = d;
    while (d < epsilon) {  // leaving the shell the ray starts in, if it does
        if (d < 0 || d < 0.5 * start) return march_to_exit(t);
        if (trace.steps >= settings.max_steps) break;
        t += epsilon;
        if (t > t_end) return trace;
        d = evaluate(t);
    }
    while (trace.steps < settings.max_steps) {
        t += d;
        if (t > t_end) return trace;
        d = evaluate(t);
        if (d < epsilon) return hit(t, false);
    }
    trace.outcome = SphereTrace::Outcome::kStepCap;
    return trace;
}

// The normalised gradient of a distance estimate by central differences of step h, or
// `fallback` where it vanishes or is not finite.
template <typename Estimate>
Normal3 estimate_normal(const Estimate& estimate, Point3 p, double h, Vector3 fallback) {
    const float hf = float(h);
    const double gx = estimate(p + Vector3{hf, 0, 0}) - estimate(p - Vector3{hf, 0, 0});
    const double gy = estimate(p + Vector3{0, hf, 0}) - estimate(p - Vector3{0, hf, 0});
    const double gz = estimate(p + Vector3{0, 0, hf}) - estimate(p - Vector3{0, 0, hf});
    const double norm = std::sqrt(gx * gx + gy * gy + gz * gz);
    if (!(norm > 0) || !std::isfinite(norm)) return Normal3(fallback);
    return normalize(Normal3(float(gx / norm), float(gy / norm), float(gz / norm)));
}

}  // namespace glint
