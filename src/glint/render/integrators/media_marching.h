// Ray marching through the participating media inside an object (shading/medium.h): the stretch
// of the ray is cut into equal intervals and the media are evaluated at one point of each; the
// light an interval adds is attenuated by the intervals before it.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>
#include <span>
#include <vector>

#include "glint/math/ray.h"
#include "glint/render/integrators/medium_stack.h"
#include "glint/render/integrators/shadow_feelers.h"
#include "glint/render/ray_stats.h"
#include "glint/render/world.h"
#include "glint/shading/fog.h"
#include "glint/shading/material.h"
#include "glint/shading/medium.h"

namespace glint {

// What the media do to the light the ray (unit direction) brings back from `length` along it:
// their transmittance, and the light they emit and scatter towards the ray's origin. In each
// interval of length ds, at the point `offset` (in [0, 1)) of the way through it, the source
// S = emission + sum over lights of scattering phase L_light (with a shadow feeler, which
// passes transparent surfaces whatever transparent_shadows says: the medium's own surface
// would otherwise shadow it) and
// sigma_t give the interval's light S (1 - exp(-sigma_t ds)) / sigma_t, exact where S and
// sigma_t are constant over it. The intervals are the most samples of the media.
FogEffect march_media(const World& world, ShadowFeelers& feelers, std::span<const Medium> media,
                      const Ray& ray, float length, float offset, RayStats& stats);

// The transmittance of the media alone over `length` along the ray (what a shadow feeler
// crossing them keeps), at the middles of a quarter as many intervals as a marched ray has.
Color media_transmittance(std::span<const Medium> media, const Ray& ray, float length);

// The media a ray inside the objects of the stack travels through: the innermost object's, or
// where that one is hollow and holds none, those of the object around it; outside every object
// (or hollow ones only), the scene's atmosphere. None where there are none.
inline const std::vector<Medium>* media_around(const World& world, const MediumStack& stack) {
    for (int level = 0; level < stack.size(); ++level) {
        const Material& m = *stack.material_out(level);
        if (!m.media.empty()) return &m.media;
        if (!m.hollow) return nullptr;
    }
    return world.atmosphere().empty() ? nullptr : &world.atmosphere();
}

// The fog of the ray (ray_fog()) with the media around it, when there are any: their light is
// added to what reaches the ray's origin, their transmittance multiplies the fog's. The
// atmosphere reaches as far as World::atmosphere_reach; a ray leaving the scene from inside an
// object (open surfaces) meets no media.
inline std::optional<FogEffect> with_media(const World& world, ShadowFeelers& feelers,
                                           const MediumStack& stack, const Ray& ray, float length,
                                           float offset, RayStats& stats,
                                           std::optional<FogEffect> fog) {
    if (stack.size() == 0 && world.atmosphere().empty()) [[likely]]
        return fog;
    const std::vector<Medium>* media = media_around(world, stack);
    if (!media) return fog;
    if (media == &world.atmosphere()) length = std::min(length, world.atmosphere_reach(ray));
    if (!(length > 0) || !std::isfinite(length)) return fog;
    const FogEffect m = march_media(world, feelers, *media, ray, length, offset, stats);
    if (!fog) return m;
    return FogEffect{fog->transmittance * m.transmittance, fog->added + m.added};
}

}  // namespace glint
