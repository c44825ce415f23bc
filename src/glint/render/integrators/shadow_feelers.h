// Shadow feelers (the notes' Schattenfühler): how much of a light reaches a surface point along
// a direction, 0 or 1, or with transparent shadows the product of what the surfaces crossed let
// through (kt, coloured by their tint) and of their insides' fade. Every integrator asks it; it
// keeps each light's last occluder per thread.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "glint/geometry/surface_point.h"
#include "glint/math/color.h"
#include "glint/math/ray.h"
#include "glint/render/ray_stats.h"
#include "glint/render/world.h"

namespace glint {

// Shadow feelers give up (and report full shadow) after crossing this many transparent surfaces.
inline constexpr int kMaxShadowCrossings = 64;

// Holds per-thread state: use one per thread, or per tile.
class ShadowFeelers {
public:
    // For lights without an index (object lights): no light buffer, no occluder cache.
    static constexpr std::size_t kNoLight = std::size_t(-1);

    // Opaque: every surface stops the feeler, whatever the scene's transparent_shadows (the
    // physically based integrators, which find light through glass by the paths it refracts).
    explicit ShadowFeelers(const World& world, bool opaque = false)
        : world_(world),
          transparent_(world.settings().transparent_shadows && !opaque),
          last_occluder_(world.lights().size(), LightBuffer::kNoPrimitive),
          last_lookup_(world.lights().size()) {}

    // The fraction of the light that reaches the surface point sp along the unit direction
    // to_light over light_distance, from world.lights()[light] (or kNoLight), per channel. n is
    // the geometric normal on the side of the light; time is the moment the shadow ray is traced
    // at. `through_transparent` passes transparent surfaces whatever transparent_shadows says:
    // a point in a medium is lit through the surface of the object that holds it.
    Color transmittance(std::size_t light, const SurfacePoint& sp, Normal3 n, Vector3 to_light,
                        float light_distance, float time, RayStats& stats,
                        bool through_transparent = false);

private:
    const World& world_;
    bool transparent_;
    std::vector<std::uint32_t> last_occluder_;  // per light
    // Per light, the last point a shadow map was asked about and its answer: a map answers for
    // the whole light at once, and an area light's samples at one point all ask it.
    struct Lookup {
        Point3 p;
        float visibility = -1;  // none yet
    };
    std::vector<Lookup> last_lookup_;
};

}  // namespace glint
