// The Mandelbulb's distance estimate and its sphere tracing.
#include "glint/geometry/mandelbulb.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "glint/geometry/number_text.h"
#include "glint/geometry/sphere_tracing.h"
#include "glint/geometry/spherical_uv.h"

namespace glint {

double Mandelbulb::escape_radius() const { return std::pow(2.0, 1.0 / (double(power) - 1)); }

double Mandelbulb::bounding_radius() const {
    // 1% and two epsilons beyond the set, so that tracing starts outside the epsilon shell.
    return double(scale) * escape_radius() * 1.01 + 2.0 * epsilon;
}

double Mandelbulb::distance_estimate(Point3 p) const {
    const double s = scale, n = power;
    const double cx = (double(p.x) - center.x) / s, cy = (double(p.y) - center.y) / s,
                 cz = (double(p.z) - center.z) / s;
    double x = cx, y = cy, z = cz;
    double r = std::sqrt(x * x + y * y + z * z);
    double dr = 1;
    for (int i = 0; i < max_iterations && r <= bailout; ++i) {
        dr = std::pow(r, n - 1) * n * dr + 1;
        if (r > 0) {
            // z^n in spherical coordinates about the +y axis: (r, theta, phi) -> (r^n, n
            // theta, n phi).
            const double theta = std::acos(std::clamp(y / r, -1.0, 1.0)) * n;
            const double phi = std::atan2(z, x) * n;
            const double rn = std::pow(r, n);
            x = rn * std::sin(theta) * std::cos(phi);
            y = rn * std::cos(theta);
            z = rn * std::sin(theta) * std::sin(phi);
        }
        x += cx;
        y += cy;
        z += cz;
        r = std::sqrt(x * x + y * y + z * z);
    }
    const double d = 0.5 * std::log(r) * r / dr * s;
    if (std::isfinite(d)) return d;
    // No value: r = 0 (the centre, inside), or dr overflowed (an orbit lingering near the
    // bailout: extremely close to the surface).
    return r < 1 ? -std::numeric_limits<double>::min() : 0.0;
}

bool Mandelbulb::inside(Point3 p) const { return distance_estimate(p) < epsilon; }

Bounds3 Mandelbulb::bounds() const {
    const float r = float(bounding_radius());
    return {center - Vector3{r, r, r}, center + Vector3{r, r, r}};
}

std::optional<ShapeHit> Mandelbulb::intersect(const Ray& ray, Interval t_range) const {
    const auto estimate = [this](Point3 p) { return distance_estimate(p); };
    const SphereTrace trace =
        sphere_trace(estimate, ray, t_range, {center, bounding_radius(), epsilon, max_steps});
    if (trace.outcome != SphereTrace::Outcome::kHit) return std::nullopt;
    ShapeHit hit{float(trace.t)};
    if (trace.leaving) hit.part = kLeavingHit;
    return hit;
}

SurfacePoint Mandelbulb::surface_at(const Ray& ray, const ShapeHit& hit) const {
    SurfacePoint sp;
    sp.p = ray.at(hit.t);
    sp.error = 2 * epsilon;  // hits land within 2 epsilon outside the set
    const auto estimate = [this](Point3 p) { return distance_estimate(p); };
    const Vector3 fallback = hit.part == kLeavingHit ? ray.direction : -ray.direction;
    sp.normal = sp.shading_normal = estimate_normal(estimate, sp.p, 0.5 * epsilon, fallback);
    sp.uv = spherical_uv(sp.p, center);
    return sp;
}

std::string describe_problem(const Mandelbulb& bulb) {
    if (!(bulb.power > 1) || !(bulb.power <= 64))
        return "mandelbulb power must be in (1, 64], got " + number_text(bulb.power);
    if (!is_finite(bulb.center)) return "mandelbulb center must be finite";
    if (!(bulb.scale > 0) || !std::isfinite(bulb.scale))
        return "mandelbulb scale must be > 0, got " + number_text(bulb.scale);
    if (!(bulb.epsilon > 0) || !std::isfinite(bulb.epsilon))
        return "mandelbulb epsilon must be > 0, got " + number_text(bulb.epsilon);
    if (bulb.max_iterations < 1 || bulb.max_iterations > 1000)
        return "mandelbulb max_iterations must be in [1, 1000], got " +
               number_text(bulb.max_iterations);
    if (bulb.max_steps < 1)
        return "mandelbulb max_steps must be >= 1, got " + number_text(bulb.max_steps);
    const double r = bulb.escape_radius();
    if (!(bulb.bailout >= r) || !(bulb.bailout <= 1e6))
        return "mandelbulb bailout must be between the escape radius " + number_text(r) +
               " and 1e6, got " + number_text(bulb.bailout);
    return {};
}

}  // namespace glint
