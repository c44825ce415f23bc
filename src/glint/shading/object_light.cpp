// The radiance of an emitting object turned into a point-light intensity for one drawn point.
#include "glint/shading/object_light.h"

#include <cmath>

#include "glint/math/constants.h"

namespace glint {

LightSample sample_light(const ObjectLight& light, Point3 p, Point2 u) {
    const SurfaceSample s = light.surface.sample_seen_from(p, u);
    const Vector3 offset = s.p - p;
    const float d2 = length_squared(offset);
    if (!(d2 > 0) || !(s.pdf > 0)) return {{0, 1, 0}, 0, Color{}};
    const float d = std::sqrt(d2);
    const Vector3 to_light = offset / d;
    const float cos_light = std::abs(dot(s.normal, to_light));
    return {to_light, d, light.radiance * (cos_light / (kPi * d2 * s.pdf))};
}

}  // namespace glint
