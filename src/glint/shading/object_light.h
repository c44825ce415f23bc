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
    std::uint32_t primitive = 0;  // the object, among the world's primitives
};

// What p receives from a point drawn on the object's surface from u in [0,1)^2, in the place of a
// point light's I_L: the Monte Carlo estimate of (1 / pi) times the radiance integrated over the
// solid angle the object fills, Le cos(theta_light) / (pi d^2 pdf_area). So a sky of radiance 1
// over the whole hemisphere lights like a directional light of 1 overhead, and Phong's diffuse
// term kd C (N.L) I_L stays what it means. Both sides of the surface emit.
LightSample sample_light(const ObjectLight& light, Point3 p, Point2 u);

}  // namespace glint
