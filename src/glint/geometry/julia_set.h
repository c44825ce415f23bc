// A quaternion Julia set (Hart, Sandin and Kauffman 1989): the 3D slice w = slice_w of the 4D
// set of quaternions q whose orbit under z <- z^2 + c stays bounded, rendered by sphere
// tracing its distance estimate.
#pragma once

#include <array>
#include <optional>
#include <string>

#include "glint/geometry/surface_point.h"
#include "glint/math/bounds.h"
#include "glint/math/interval.h"
#include "glint/math/ray.h"

namespace glint {

struct JuliaSet {
    // The constant c = c[0] + c[1] i + c[2] j + c[3] k. Finite.
    std::array<float, 4> c{};
    // The point p of the scene is the quaternion ((p - center) / scale, slice_w): x is the real
    // part, y, z and slice_w the i, j and k parts.
    float slice_w = 0;
    int max_iterations = 10;  // >= 1
    // A hit is where the distance estimate (world units) drops below epsilon. > 0.
    float epsilon = 1e-3f;
    // Escape radius: the iteration stops once |z| > bailout. >= escape_radius(), <= 1e6.
    float bailout = 4;
    Point3 center;
    float scale = 1;      // > 0
    int max_steps = 512;  // sphere-tracing steps per ray; then the ray misses. >= 1.

    // R = (1 + sqrt(1 + 4|c|)) / 2: an orbit that leaves the ball |z| <= R never returns, so
    // the whole set lies inside it (local units).
    double escape_radius() const;
    // The radius (world units) of the sphere about `center` that holds the slice, with a
    // margin for the epsilon shell. 0 when the slice misses the set's ball: |slice_w| >= R.
    double bounding_radius() const;
    // |z| log|z| / (2 |z'|) after the iteration, z' the running derivative 2 z z' (Hart et al.
    // 1989), in world units. A lower bound of the distance outside the set; <= 0 inside.
    // Never NaN: where the formula has no value (z or z' underflowed or exactly 0) it is a
    // tiny negative number if |z| < 1 (inside) and 0 otherwise.
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
std::string describe_problem(const JuliaSet& julia);

}  // namespace glint
