// Whitted's recursive ray tracer (1980), exactly the lecture notes' TraceRay: the closest hit,
// Phong's local term with one shadow feeler per light, and the reflected and refracted rays,
// the ray tree cut by depth and by contribution weight:
//   I = emission + ka Ia C + sum_lights shadow IL (kd C (N.L) + ks spec^n)
//       + kr I(reflected) + kt I(refracted)
#pragma once

#include <vector>

#include "glint/geometry/surface_point.h"
#include "glint/math/color.h"
#include "glint/math/ray.h"
#include "glint/render/ray_stats.h"
#include "glint/render/world.h"
#include "glint/sampling/sampler.h"

namespace glint {

// Holds per-thread state (each light's last occluder, for the shadow cache): use one
// integrator per thread, or per tile.
class WhittedIntegrator {
public:
    explicit WhittedIntegrator(const World& world)
        : world_(world), last_occluder_(world.lights().size(), LightBuffer::kNoPrimitive) {}

    // The colour seen along an eye ray. Counts every ray it traces, the eye ray included.
    Color trace_eye_ray(const Ray& ray, RayStats& stats);
    // The render loop's form: Whitted's ray tracer draws no random numbers of its own.
    Color trace_eye_ray(const Ray& ray, SampleStream&, RayStats& stats) {
        return trace_eye_ray(ray, stats);
    }

    // The colour seen along a ray at the given depth of the ray tree (eye rays are depth 1)
    // whose contribution to the pixel is scaled by weight (the product of kr and kt above it).
    Color trace(const Ray& ray, int depth, float weight, RayStats& stats);

    // The fraction of the intensity of lights()[light] that reaches the surface point along the
    // unit direction to_light over light_distance: 0 or 1, or with transparent shadows the
    // product of the transmit weights of the surfaces crossed. n is the geometric normal on the
    // side of the light.
    float shadow_factor(std::size_t light, const SurfacePoint& sp, Normal3 n, Vector3 to_light,
                        float light_distance, RayStats& stats);

private:
    const World& world_;
    std::vector<std::uint32_t> last_occluder_;  // per light
};

// Shadow feelers give up (and report full shadow) after crossing this many transparent surfaces.
inline constexpr int kMaxShadowCrossings = 64;

}  // namespace glint
