// Light sources of the classic model: point lights (with optional distance attenuation) and
// directional lights. The global ambient term lives in the scene.
#pragma once

#include <variant>

#include "glint/math/color.h"
#include "glint/math/vector.h"

namespace glint {

// Intensity at distance d is color / (constant + linear d + quadratic d^2).
struct Attenuation {
    float constant = 1;
    float linear = 0;
    float quadratic = 0;
};

struct PointLight {
    Point3 position;
    Color color{1, 1, 1};
    Attenuation attenuation;
};

struct DirectionalLight {
    Vector3 direction{0, -1, 0};  // unit; the way the light travels
    Color color{1, 1, 1};
};

using Light = std::variant<PointLight, DirectionalLight>;

// What a surface point receives from one light, before shadowing.
struct LightSample {
    Vector3 to_light;  // unit direction L from the point towards the light
    float distance;    // to the light; infinite for directional lights
    Color intensity;   // I_L, attenuated
};

LightSample sample_light(const Light& light, Point3 p);

}  // namespace glint
