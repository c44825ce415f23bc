// The radiance of an emitting object turned into a point-light intensity for one drawn point.
#include "glint/shading/object_light.h"

#include <cmath>

#include "glint/math/constants.h"

namespace glint {

LightSample sample_light(const ObjectLight& light, Point3 p, Point2 u) {
    return sample_object_light(light, p, u).light;
}

ObjectLightSample sample_object_light(const ObjectLight& light, Point3 p, Point2 u) {
    const SurfaceSample s = light.surface.sample_seen_from(p, u);
    const Vector3 offset = s.p - p;
    const float d2 = length_squared(offset);
    if (!(d2 > 0) || !(s.pdf > 0)) return {{{0, 1, 0}, 0, Color{}}, 0};
    const float d = std::sqrt(d2);
    const Vector3 to_light = offset / d;
    const float cos_light = std::abs(dot(s.normal, to_light));
    // p behind a one-sided emitter: it is drawn on, but sends nothing this way.
    const bool lit = light.both_sides || dot(s.normal, to_light) < 0;
    return {{to_light, d, lit ? light.radiance * (cos_light / (kPi * d2 * s.pdf)) : Color{}},
            cos_light > 0 ? s.pdf * d2 / cos_light : 0};
}

float object_light_pdf(const ObjectLight& light, Point3 p, Point3 q, Normal3 n) {
    const Vector3 offset = q - p;
    const float d2 = length_squared(offset);
    const float cos_light = std::abs(dot(n, offset)) / std::sqrt(d2);
    if (!(d2 > 0) || !(cos_light > 0)) return 0;
    return light.surface.pdf_seen_from(p, q, n) * d2 / cos_light;
}

Color object_light_power(const ObjectLight& light) {
    return light.radiance * ((light.both_sides ? 2 : 1) * kPi * light.surface.area());
}

}  // namespace glint
