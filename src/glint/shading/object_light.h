// An object whose material emits light, as a light: shadow rays aim at points drawn on its
// surface. Its emission is radiance, so a point receives what the surface subtends: a large
// emitter nearby lights more than a small one far away.
#pragma once

#include <cstdint>

#include "glint/geometry/surface_sampler.h"
#include "glint/math/color.h"
#include "glint/shading/light.h"

namespace glint {

struct ObjectLight {
    SurfaceSampler surface;
    Color radiance;               // the material's emission, Le
    bool both_sides = true;       // else only the side the surface's normal points to emits
    std::uint32_t primitive = 0;  // the object, among the world's primitives
};

// What p receives from a point drawn on the object's surface from u in [0,1)^2, in the place of a
// point light's I_L: the Monte Carlo estimate of (1 / pi) times the radiance integrated over the
// solid angle the object fills, Le cos(theta_light) / (pi d^2 pdf_area). So a sky of radiance 1
// over the whole hemisphere lights like a directional light of 1 overhead, and Phong's diffuse
// term kd C (N.L) I_L stays what it means. Both sides of the surface emit.
LightSample sample_light(const ObjectLight& light, Point3 p, Point2 u);

// The same sample with the density it was drawn with, per steradian as seen from p (0 when
// there is nothing to draw): radiance is then Le = pi I_L, and Le / pdf its estimate.
struct ObjectLightSample {
    LightSample light;
    float pdf = 0;
};
ObjectLightSample sample_object_light(const ObjectLight& light, Point3 p, Point2 u);
// The density per steradian with which sample_object_light from p draws the point q of the
// object's surface (unit normal n there): what multiple importance sampling weighs a ray that
// found q by another strategy with.
float object_light_pdf(const ObjectLight& light, Point3 p, Point3 q, Normal3 n);
// The power it emits, pi Le A from each emitting side of area A.
Color object_light_power(const ObjectLight& light);

}  // namespace glint
