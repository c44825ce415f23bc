// What a point receives from each kind of light: direction, distance and attenuated intensity.
#include "glint/shading/light.h"

#include "glint/math/interval.h"

namespace glint {

namespace {
struct Sample {
    Point3 p;

    LightSample operator()(const PointLight& light) const {
        const Vector3 offset = light.position - p;
        const float d = length(offset);
        const Attenuation& a = light.attenuation;
        return {offset / d, d, light.color / (a.constant + d * (a.linear + d * a.quadratic))};
    }
    LightSample operator()(const DirectionalLight& light) const {
        return {-light.direction, kInfinity, light.color};
    }
};
}  // namespace

LightSample sample_light(const Light& light, Point3 p) { return std::visit(Sample{p}, light); }

}  // namespace glint
