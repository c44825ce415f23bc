// A participating medium filling an object's inside (POV-Ray's media): per unit length it
// absorbs, emits and scatters light, each scaled by a density that may vary from point to point.
// Along a stretch of length ds at density d, light is extinguished by exp(-sigma_t ds) with
//   sigma_t = d (absorption + extinction scattering),
// and the stretch adds d emission ds plus what it scatters towards the viewer of each light:
//   d scattering phase(cos theta) L_light ds,
// theta the angle the light turns through (cos theta = the direction to the light . the ray's).
// The phase functions are weighed so that their mean over the sphere is 1 (4 pi times the
// probability density), so that an isotropic medium scatters 1 towards every direction.
#pragma once

#include <string>
#include <vector>

#include "glint/math/color.h"
#include "glint/math/vector.h"
#include "glint/shading/texture.h"

namespace glint {

enum class PhaseKind {
    isotropic,          // 1
    rayleigh,           // 3/4 (1 + cos^2): small particles, the blue sky
    mie_hazy,           // (1 + 9 u^8) / 2, u = (1 + cos) / 2: a thin haze, mostly forwards
    mie_murky,          // 33/83 (1 + 50 u^32): a murky one, more so
    henyey_greenstein,  // (1 - g^2) / (1 + g^2 - 2 g cos)^(3/2), g the eccentricity
};

struct Medium {
    Color absorption;  // per unit length, >= 0
    Color emission;    // light added per unit length, >= 0
    Color scattering;  // per unit length, >= 0
    PhaseKind phase = PhaseKind::isotropic;
    float eccentricity = 0;  // g of henyey_greenstein, in (-1, 1): > 0 forwards
    // How much of the scattered light the medium takes away from the light crossing it, 0 to 1
    // (1: all, as physics has it; POV-Ray's extinction).
    float extinction = 1;
    // The density's factors, multiplied per channel (none: 1 everywhere); each evaluated at the
    // point as a texture is, in the scene's space.
    std::vector<Texture> density;
    // Where along a ray through the medium it is evaluated: this many points, one in each of as
    // many equal intervals.
    int samples = 10;
};

// The most media one object holds.
inline constexpr std::size_t kMaxMedia = 8;

// The phase function's value for cos theta in [-1, 1].
float phase_value(PhaseKind kind, float eccentricity, float cos_theta);

// The product of the density factors at p (1 without any).
Color density_at(const Medium& medium, Point3 p);

// sigma_t at density `density`.
inline Color extinction_of(const Medium& medium, const Color& density) {
    return density * (medium.absorption + medium.extinction * medium.scattering);
}

// What is wrong with a medium's numbers as a scene gave them, or "".
std::string describe_problem(const Medium& medium);

}  // namespace glint
