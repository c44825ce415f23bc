// Moving a ray's origin to its point nearest a centre, in double, before a shape solves for t.
#include "glint/geometry/near_ray.h"

namespace glint {

NearRay near_ray(const Ray& ray, Vector3d center) {
    const Vector3d d(ray.direction);
    const Vector3d to_center = center - Vector3d(ray.origin);
    const double t_shift = dot(to_center, d) / dot(d, d);
    // The new origin relative to the centre: t_shift d - (C - O), exact to double rounding.
    return {d * t_shift - to_center, d, t_shift};
}

}  // namespace glint
