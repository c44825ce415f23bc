// The general quadric surface A x^2 + B y^2 + C z^2 + D xy + E xz + F yz + G x + H y + I z + J = 0
// in world coordinates, clipped to a box: ellipsoids, hyperboloids, paraboloids, cones,
// cylinders and planes in one description (the notes' implicit surfaces of second order).
#pragma once

#include <array>
#include <optional>
#include <string>

#include "glint/geometry/surface_point.h"
#include "glint/math/bounds.h"
#include "glint/math/interval.h"
#include "glint/math/ray.h"

namespace glint {

struct Quadric {
    std::array<float, 10> coefficients{};  // A..J in that order
    Bounds3 clip;                          // finite; only the part of the surface inside is kept

    // The clip box (the surface part inside is not bounded more tightly).
    Bounds3 bounds() const;
    // f(O + t R) = alpha t^2 + beta t + gamma is solved in double (solve_quadratic_double), keeping
    // the roots whose points lie inside `clip`. The ray is first cut to the clip box (slabs) and
    // its origin moved to the middle of that chord, in double, so the coefficients are of the box's
    // size however far away the ray starts; each root gets one Newton step in double. Zero
    // second-order terms (a plane) or a ray along a ruling (alpha = 0) leave a linear equation.
    std::optional<ShapeHit> intersect(const Ray& ray, Interval t_range) const;
    // The point gets a Newton step onto f = 0 along the gradient. The normal is the gradient's
    // direction (2Ax + Dy + Ez + G, 2By + Dx + Fz + H, 2Cz + Ex + Fy + I), the side where f > 0;
    // at a singular point (the apex of a cone, zero gradient) it faces back along the ray. uv is
    // the point's x and z across the clip box, each in [0, 1] (a projection along y).
    SurfacePoint surface_at(const Ray& ray, const ShapeHit& hit) const;
};

// The box of the quadric's inside (f < 0) when its axes are the coordinate axes (D = E = F = 0):
// completing the squares, sum a_i (x_i - c_i)^2 < K with every a_i >= 0 bounds |x_i - c_i| by
// sqrt(K / a_i) where a_i > 0 (an ellipsoid on all three axes, a cylinder on two), and leaves
// the axes without a square term (and no linear one) unbounded; empty when K <= 0. Otherwise
// (cross terms, a negative square, a linear term alone: cones, hyperboloids, paraboloids, planes)
// unbounded on every axis.
Bounds3 inside_extent(const std::array<float, 10>& coefficients);

// f and its gradient at a point, in double.
double quadric_value(const Quadric& quadric, double x, double y, double z);
std::array<double, 3> quadric_gradient(const Quadric& quadric, double x, double y, double z);

// Empty when the quadric is valid, else what is wrong, e.g.
// "quadric clip box must be finite and min <= max on every axis".
std::string describe_problem(const Quadric& quadric);

}  // namespace glint
