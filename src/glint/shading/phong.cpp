// The notes' diffuse and specular terms (Blinn's H.N or Phong's R.V) of one light.
#include "glint/shading/phong.h"

#include <cmath>

#include "glint/shading/optics.h"

namespace glint {

float specular_factor(Highlight model, Normal3 n, Vector3 to_light, Vector3 to_viewer,
                      float shininess) {
    if (dot(n, to_light) <= 0 || dot(n, to_viewer) <= 0) return 0;
    float c = 0;
    switch (model) {
        case Highlight::blinn:
            c = dot(n, normalize(to_light + to_viewer));
            break;
        case Highlight::phong:
            c = dot(reflect(-to_light, n), to_viewer);
            break;
    }
    return c > 0 ? std::pow(c, shininess) : 0;
}

Color light_term(const Material& m, Color surface_color, Normal3 n, Vector3 to_light,
                 Vector3 to_viewer, Color light_intensity) {
    const float diffuse = m.kd * diffuse_factor(n, to_light, m.brilliance);
    const float specular =
        m.ks > 0 ? m.ks * specular_factor(m.highlight, n, to_light, to_viewer, m.shininess) : 0;
    return light_intensity *
           (diffuse * surface_color + specular * highlight_color(m, surface_color));
}

}  // namespace glint
