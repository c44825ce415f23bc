// A ray moved close to a shape before solving, so that rays from far away stay accurate.
#pragma once

#include "glint/math/ray.h"
#include "glint/math/vector3d.h"

namespace glint {

// A ray re-expressed near a shape: its origin moved along it to the point closest to `center`,
// then made relative to `center`, all in double. The round shapes solve for s on this ray and
// hit at t = t_shift + s; their quadratics and quartics then have coefficients of the shape's own
// size, however far away the ray starts. (Solving with the far origin loses the answer: the
// constant term |O - C|^2 - r^2 of a ray from 1e4 away has float rounding errors of order 1.)
struct NearRay {
    Vector3d origin;  // relative to the centre
    Vector3d direction;
    double t_shift;
};
NearRay near_ray(const Ray& ray, Vector3d center);

}  // namespace glint
