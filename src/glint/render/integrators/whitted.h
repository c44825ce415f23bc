// Whitted's recursive ray tracer (1980), exactly the lecture notes' TraceRay: the closest hit,
// Phong's local term with one shadow feeler per light, and the reflected and refracted rays,
// the ray tree cut by depth and by contribution weight:
//   I = emission + ka Ia C + sum_lights shadow IL (kd C (N.L) + ks spec^n)
//       + kr I(reflected) + kt I(refracted)
#pragma once

#include <optional>

#include "glint/math/color.h"
#include "glint/math/ray.h"
#include "glint/render/integrators/medium_stack.h"
#include "glint/render/integrators/ray_recorder.h"
#include "glint/render/integrators/shadow_feelers.h"
#include "glint/render/ray_stats.h"
#include "glint/render/world.h"
#include "glint/sampling/sampler.h"

namespace glint {

// Holds per-thread state (each light's last occluder, for the shadow cache): use one
// integrator per thread, or per tile.
class WhittedIntegrator {
public:
    // Its tiles share nothing.
    struct Shared {};
    static Shared prepare(const World&) { return {}; }

    explicit WhittedIntegrator(const World& world) : world_(world), feelers_(world) {}
    WhittedIntegrator(const World& world, const Shared&) : WhittedIntegrator(world) {}

    // The colour seen along an eye ray, which may carry its pencil (pencil.h; null: none).
    // Counts every ray it traces, the eye ray included.
    Color trace_eye_ray(const Ray& ray, RayStats& stats, const RayDifferential* pencil = nullptr);
    // The render loop's form: Whitted's ray tracer draws no random numbers of its own. An area
    // light is a point light at its centre; objects that emit light only glow.
    Color trace_eye_ray(const Ray& ray, const RayDifferential* pencil, SampleStream&,
                        RayStats& stats) {
        return trace_eye_ray(ray, stats, pencil);
    }
    // The same, given the eye ray's nearest hit, found with the rays of neighbouring pixels in
    // one packet (World::nearest_hits).
    Color trace_eye_ray(const Ray& ray, const std::optional<Hit>& hit,
                        const RayDifferential* pencil, SampleStream& stream, RayStats& stats);

    // The colour seen along a ray at the given depth of the ray tree (eye rays are depth 1)
    // whose contribution to the pixel is scaled by weight (the product of kr and kt above it),
    // travelling through the given media. Rough surfaces reflect and refract as mirrors do.
    // The pencil, when the ray carries one, follows it through mirrors and glass.
    Color trace(const Ray& ray, int depth, float weight, RayStats& stats,
                const MediumStack& media = kVacuum, const RayDifferential* pencil = nullptr);

    // Records every ray it traces from now on into `recorder` (glint explain, output variables);
    // null stops.
    void record_into(RayRecorder* recorder) { recorder_ = recorder; }

private:
    // A ray traced and told to the recorder.
    Color trace_recorded(const Ray& ray, int depth, float weight, RayStats& stats,
                         const MediumStack& media, const RayDifferential* pencil);
    template <bool kRecord>
    Color trace_ray(const Ray& ray, int depth, float weight, RayStats& stats,
                    const MediumStack& media, const RayDifferential* pencil);
    // The colour along a ray whose nearest hit is `hit`.
    template <bool kRecord>
    Color shade(const Ray& ray, const std::optional<Hit>& hit, int depth, float weight,
                RayStats& stats, const MediumStack& media, const RayDifferential* pencil);

    const World& world_;
    ShadowFeelers feelers_;
    RayRecorder* recorder_ = nullptr;
};

}  // namespace glint
