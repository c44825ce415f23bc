// Sphere tracing (Hart 1996, "Sphere tracing: a geometric method for the antialiased ray
// tracing of implicit surfaces"): step along the ray by a lower bound of the distance to the
// surface until it falls below epsilon. Shared by the distance-estimated fractals.
#pragma once

#include <algorithm>
#include <cmath>

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
    double t = 0;   // of the hit
    int steps = 0;  // estimates evaluated
};

// `estimate(Point3)` returns a distance estimate in world units: a lower bound of the distance
// to the surface outside it, <= 0 inside. Hits satisfy estimate < epsilon. A ray that starts
// within the epsilon shell (a shadow or reflection ray leaving a hit point) first walks out of
// it in steps of epsilon. It is entering the surface, and hits at its start, if the estimate
// there is negative or falls below half its starting value on the way.
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

    const auto at = [&](double t) {
        return Point3(float(ray.origin.x + t * ray.direction.x),
                      float(ray.origin.y + t * ray.direction.y),
                      float(ray.origin.z + t * ray.direction.z));
    };
    const auto hit = [&](double t) {
        trace.outcome = SphereTrace::Outcome::kHit;
        trace.t = t;
        return trace;
    };

    double t = t_begin;
    double d = estimate(at(t));
    ++trace.steps;
    const double start = d;
    while (d < settings.epsilon) {  // leaving the shell the ray starts in, if it does
        if (d < 0 || d < 0.5 * start) return hit(t_begin);
        if (trace.steps >= settings.max_steps) break;
        t += settings.epsilon;
        if (t > t_end) return trace;
        d = estimate(at(t));
        ++trace.steps;
    }
    while (trace.steps < settings.max_steps) {
        t += d;
        if (t > t_end) return trace;
        d = estimate(at(t));
        ++trace.steps;
        if (d < settings.epsilon) return hit(t);
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
