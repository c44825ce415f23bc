// The quaternion Julia set's distance estimate and its sphere tracing.
#include "glint/geometry/julia_set.h"

#include <cmath>
#include <limits>

#include "glint/geometry/number_text.h"
#include "glint/geometry/sphere_tracing.h"
#include "glint/geometry/spherical_uv.h"

namespace glint {

double JuliaSet::escape_radius() const {
    const double c_norm = std::sqrt(double(c[0]) * c[0] + double(c[1]) * c[1] +
                                    double(c[2]) * c[2] + double(c[3]) * c[3]);
    // For |z| > R, |z^2 + c| >= |z|^2 - |c| > |z|: R is the root of R^2 - R - |c| = 0.
    return (1 + std::sqrt(1 + 4 * c_norm)) / 2;
}

double JuliaSet::bounding_radius() const {
    const double r = escape_radius();
    const double slice = r * r - double(slice_w) * slice_w;
    if (!(slice > 0)) return 0;
    // 1% and two epsilons beyond the set, so that tracing starts outside the epsilon shell.
    return double(scale) * std::sqrt(slice) * 1.01 + 2.0 * epsilon;
}

double JuliaSet::distance_estimate(Point3 p) const {
    const double s = scale;
    // z = a + v (real part a, vector part v): z^2 = a^2 - |v|^2 + 2 a v.
    double a = (double(p.x) - center.x) / s, v1 = (double(p.y) - center.y) / s,
           v2 = (double(p.z) - center.z) / s, v3 = slice_w;
    double r2 = a * a + v1 * v1 + v2 * v2 + v3 * v3;
    double dz = 1;  // |z'|, the running derivative
    const double bailout2 = double(bailout) * bailout;
    for (int i = 0; i < max_iterations && r2 <= bailout2; ++i) {
        dz *= 2 * std::sqrt(r2);
        const double a2 = a * a - v1 * v1 - v2 * v2 - v3 * v3 + c[0];
        v1 = 2 * a * v1 + c[1];
        v2 = 2 * a * v2 + c[2];
        v3 = 2 * a * v3 + c[3];
        a = a2;
        r2 = a * a + v1 * v1 + v2 * v2 + v3 * v3;
    }
    const double r = std::sqrt(r2);
    const double d = 0.5 * r * std::log(r) / dz * s;
    if (std::isfinite(d)) return d;
    // No value: an orbit that collapsed to 0 (deep inside: r and dz underflow) or passed
    // through 0 exactly (dz = 0). Inside or on the surface, by the sign convention.
    return r < 1 ? -std::numeric_limits<double>::min() : 0.0;
}

bool JuliaSet::inside(Point3 p) const { return distance_estimate(p) < epsilon; }

Bounds3 JuliaSet::bounds() const {
    const float r = float(bounding_radius());
    return {center - Vector3{r, r, r}, center + Vector3{r, r, r}};
}

std::optional<ShapeHit> JuliaSet::intersect(const Ray& ray, Interval t_range) const {
    const double radius = bounding_radius();
    if (!(radius > 0)) return std::nullopt;
    const auto estimate = [this](Point3 p) { return distance_estimate(p); };
    const SphereTrace trace =
        sphere_trace(estimate, ray, t_range, {center, radius, epsilon, max_steps});
    if (trace.outcome != SphereTrace::Outcome::kHit) return std::nullopt;
    ShapeHit hit{float(trace.t)};
    if (trace.leaving) hit.part = kLeavingHit;
    return hit;
}

SurfacePoint JuliaSet::surface_at(const Ray& ray, const ShapeHit& hit) const {
    SurfacePoint sp;
    sp.p = ray.at(hit.t);
    sp.error = 2 * epsilon;  // hits land within 2 epsilon outside the set
    const auto estimate = [this](Point3 p) { return distance_estimate(p); };
    const Vector3 fallback = hit.part == kLeavingHit ? ray.direction : -ray.direction;
    sp.normal = sp.shading_normal = estimate_normal(estimate, sp.p, 0.5 * epsilon, fallback);
    sp.uv = spherical_uv(sp.p, center);
    return sp;
}

std::string describe_problem(const JuliaSet& julia) {
    for (const float ci : julia.c)
        if (!std::isfinite(ci)) return "julia c must be finite";
    if (!std::isfinite(julia.slice_w)) return "julia slice_w must be finite";
    if (!is_finite(julia.center)) return "julia center must be finite";
    if (!(julia.scale > 0) || !std::isfinite(julia.scale))
        return "julia scale must be > 0, got " + number_text(julia.scale);
    if (!(julia.epsilon > 0) || !std::isfinite(julia.epsilon))
        return "julia epsilon must be > 0, got " + number_text(julia.epsilon);
    if (julia.max_iterations < 1 || julia.max_iterations > 1000)
        return "julia max_iterations must be in [1, 1000], got " +
               number_text(julia.max_iterations);
    if (julia.max_steps < 1)
        return "julia max_steps must be >= 1, got " + number_text(julia.max_steps);
    const double r = julia.escape_radius();
    if (!(julia.bailout >= r) || !(julia.bailout <= 1e6))
        return "julia bailout must be between the escape radius " + number_text(r) +
               " and 1e6, got " + number_text(julia.bailout);
    return {};
}

}  // namespace glint
