// The phase functions and the density of a participating medium.
#include "glint/shading/medium.h"

#include <cmath>

namespace glint {

float phase_value(PhaseKind kind, float eccentricity, float cos_theta) {
    const float u = (1 + cos_theta) / 2;
    switch (kind) {
        case PhaseKind::isotropic:
            return 1;
        case PhaseKind::rayleigh:
            return 0.75f * (1 + cos_theta * cos_theta);
        case PhaseKind::mie_hazy:
            return 0.5f * (1 + 9 * std::pow(u, 8.f));
        case PhaseKind::mie_murky:
            return 33.f / 83 * (1 + 50 * std::pow(u, 32.f));
        case PhaseKind::henyey_greenstein: {
            const float g = eccentricity;
            return (1 - g * g) / std::pow(1 + g * g - 2 * g * cos_theta, 1.5f);
        }
    }
    return 1;
}

Color density_at(const Medium& medium, Point3 p) {
    Color d{1, 1, 1};
    if (medium.density.empty()) return d;
    SurfacePoint at;
    at.p = p;
    for (const Texture& factor : medium.density) d *= evaluate(factor, at);
    return d;
}

std::string describe_problem(const Medium& medium) {
    const auto non_negative = [](const Color& c) {
        return c.r >= 0 && c.g >= 0 && c.b >= 0 && std::isfinite(c.r) && std::isfinite(c.g) &&
               std::isfinite(c.b);
    };
    if (!non_negative(medium.absorption)) return "medium absorption must be finite and >= 0";
    if (!non_negative(medium.emission)) return "medium emission must be finite and >= 0";
    if (!non_negative(medium.scattering)) return "medium scattering must be finite and >= 0";
    if (!(medium.eccentricity > -1 && medium.eccentricity < 1))
        return "medium eccentricity must be in (-1, 1)";
    if (!(medium.extinction >= 0 && medium.extinction <= 1))
        return "medium extinction must be in [0, 1]";
    if (!(medium.samples >= 1 && medium.samples <= 1000))
        return "medium samples must be from 1 to 1000";
    return "";
}

}  // namespace glint
