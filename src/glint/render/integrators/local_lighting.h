// The local term of the notes' illumination model, light by light: Phong's terms of one light
// sample, with its shadow feeler. Shared by every integrator; they differ in which samples of a
// light they take.
#pragma once

#include <cstddef>

#include "glint/render/integrators/shadow_feelers.h"
#include "glint/render/integrators/surface_context.h"
#include "glint/render/ray_stats.h"
#include "glint/shading/light.h"
#include "glint/shading/phong.h"

namespace glint {

// shadow IL (kd C (N.L) + ks spec^n) for the light sample ls of light `light` (an index of
// world.lights(), or ShadowFeelers::kNoLight); nothing, and no feeler, when the light is behind
// the surface or sends nothing this way.
inline Color light_sample_term(ShadowFeelers& feelers, std::size_t light, const SurfaceContext& c,
                               const LightSample& ls, float time, RayStats& stats) {
    // A light behind the surface adds nothing, so it needs no feeler. (The sum tells black
    // apart in fewer instructions than is_black: channels are not negative.)
    if (dot(c.n, ls.to_light) <= 0 || ls.intensity.r + ls.intensity.g + ls.intensity.b <= 0)
        return {};
    const Color shadow =
        feelers.transmittance(light, c.sp, c.ng, ls.to_light, ls.distance, time, stats);
    if (is_black(shadow)) return {};
    return shadow * light_term(*c.material, c.color, c.n, ls.to_light, c.to_viewer, ls.intensity);
}

}  // namespace glint
