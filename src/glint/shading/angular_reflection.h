// How a surface's mirror reflection varies with the angle of incidence theta, as POV-Ray's
// reflection { min max falloff fresnel metallic } makes it vary: kr runs from its value facing
// the viewer (cos theta = 1) to the material's reflect at grazing incidence, and a metallic
// reflection takes the surface colour facing the viewer and stays white at grazing incidence.
#pragma once

#include <algorithm>
#include <cmath>

#include "glint/math/color.h"
#include "glint/math/constants.h"
#include "glint/shading/optics.h"

namespace glint {

struct AngularReflection {
    float facing = 0;  // kr where the viewer looks along the normal, >= 0
    // kr = facing + (grazing - facing) w with w = (1 - cos theta)^falloff, or with `fresnel`
    // w = Fresnel's reflectance of a dielectric of the object's index.
    float falloff = 1;  // > 0
    bool fresnel = false;
};

// kr at the angle whose cosine is cos_theta (in [0, 1]) for a material whose kr at grazing
// incidence is `grazing`; eta = n_outside / n_inside across the surface, for fresnel.
inline float reflect_at(const AngularReflection& a, float grazing, float cos_theta, float eta) {
    cos_theta = std::clamp(cos_theta, 0.0f, 1.0f);
    const float w =
        a.fresnel ? fresnel_dielectric(cos_theta, eta) : std::pow(1 - cos_theta, a.falloff);
    return a.facing + (grazing - a.facing) * w;
}

// What a metallic reflection multiplies kr by, channel by channel: 1 + M (1 - F)(C - 1), with
// M the metallic amount, C the surface colour and F POV-Ray's empirical curve of the angle x
// (theta over a right angle), 0 facing the viewer and 1 at grazing incidence:
// F = 0.014567225 / (x - 1.12)^2 - 0.011612903.
inline Color metallic_reflection(float metallic, Color c, float cos_theta) {
    const float x = std::acos(std::clamp(cos_theta, 0.0f, 1.0f)) / (kPi / 2);
    const float f =
        std::clamp(0.014567225f / ((x - 1.12f) * (x - 1.12f)) - 0.011612903f, 0.0f, 1.0f);
    const float k = metallic * (1 - f);
    return Color{1 + k * (c.r - 1), 1 + k * (c.g - 1), 1 + k * (c.b - 1)};
}

}  // namespace glint
