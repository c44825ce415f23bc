// The Mandelbulb (White and Nylander 2009): points c whose orbit under z <- z^power + c stays
// bounded, with the power of a 3D point taken in spherical coordinates (r^n, n theta, n phi);
// rendered by sphere tracing its distance estimate.
#pragma once

#include <optional>
#include <string>

#include "glint/geometry/surface_point.h"
#include "glint/math/bounds.h"
#include "glint/math/interval.h"
#include "glint/math/ray.h"

namespace glint {

struct Mandelbulb {
    float power = 8;          // > 1, <= 64
    int max_iterations = 12;  // >= 1
    // A hit is where the distance estimate (world units) drops below epsilon. > 0.
    float epsilon = 1e-3f;
    // Escape radius: the iteration stops once |z| > bailout. >= escape_radius(), <= 1e6.
    float bailout = 2;
    // The point p of the scene is c = (p - center) / scale. The polar axis (theta = 0) is +y.
    Point3 center;
    float scale = 1;      // > 0
    int max_steps = 512;  // sphere-tracing steps per ray; then the ray misses. >= 1.

    // R = 2^(1 / (power - 1)): for |c| > R, |z^n + c| >= |z|^n - |z| > |z| and the orbit
    // escapes, so the set lies in the ball of radius R (1.104 for power 8; local units).
    double escape_radius() const;
    // The radius (world units) of the sphere about `center` that holds the set, with a margin
    // for the epsilon shell.
    double bounding_radius() const;
    // 0.5 log(r) r / dr after the iteration, dr the running derivative n r^(n-1) dr + 1
    // (Hvidtfeldt Christensen 2011), in world units; <= 0 inside. Never NaN: where the
    // formula has no value it is a tiny negative number if r < 1 (the centre) and 0 otherwise.
    double distance_estimate(Point3 p) const;

    // Whether p is inside the solid that rays see: distance_estimate(p) < epsilon, the set
    // grown by the epsilon shell in which sphere tracing stops. This is the solid a CSG uses.
    bool inside(Point3 p) const;

    Bounds3 bounds() const;
    // The first crossing of the solid's surface: where the ray enters it, or, for a ray that
    // starts inside, where it leaves (hit.part = kLeavingHit). See sphere_trace().
    std::optional<ShapeHit> intersect(const Ray& ray, Interval t_range) const;
    // normal: central differences of the estimate with step epsilon / 2, pointing out of the
    // solid. uv: spherical about `center`, as for Sphere.
    SurfacePoint surface_at(const Ray& ray, const ShapeHit& hit) const;
};

// What is wrong with the parameters, for the loader to report; empty when they are valid.
std::string describe_problem(const Mandelbulb& bulb);

}  // namespace glint
