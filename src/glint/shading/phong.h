// Phong's local illumination model as the lecture notes state it:
//   I_local = ka Ia C + sum over lights of shadow IL (kd C (N.L)^b + ks S spec^n)
// where C is the surface colour, spec is H.N (Blinn) or R.V (Phong), b the brilliance (1 in the
// notes) and S the highlight's colour, white unless the material is metallic.
#pragma once

#include <cmath>

#include "glint/math/color.h"
#include "glint/math/vector.h"
#include "glint/shading/material.h"

namespace glint {

// ka Ia C.
constexpr Color ambient_term(const Material& m, Color surface_color, Color ambient_light) {
    return m.ka * ambient_light * surface_color;
}

// (N.L)^brilliance, or 0 when the light is behind the surface.
inline float diffuse_factor(Normal3 n, Vector3 to_light, float brilliance = 1) {
    const float c = dot(n, to_light);
    if (!(c > 0)) return 0;
    return brilliance == 1 ? c : std::pow(c, brilliance);
}

// S: white, mixed towards the surface colour by the material's metallic.
constexpr Color highlight_color(const Material& m, Color surface_color) {
    return Color::gray(1 - m.metallic) + m.metallic * surface_color;
}

// spec^n with spec = H.N (H = normalize(L + V)) or R.V (R = L mirrored about N); 0 when the
// light or the viewer is behind the surface. n, l, v are unit; v points towards the viewer.
float specular_factor(Highlight model, Normal3 n, Vector3 to_light, Vector3 to_viewer,
                      float shininess);

// IL (kd C (N.L)^b + ks S spec^n): one unshadowed light's share of the local term.
Color light_term(const Material& m, Color surface_color, Normal3 n, Vector3 to_light,
                 Vector3 to_viewer, Color light_intensity);

}  // namespace glint
