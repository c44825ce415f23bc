// Cook, Porter and Carpenter's distributed ray tracing (1984): Whitted's ray tree, each of its
// rays spread over what it integrates by the sample's own random numbers. Eye rays spread over
// the pixel (and the lens and the shutter, in the camera); shadow rays over the area of each
// light, stratified across the pixel's samples; reflected and refracted rays over the glossy
// lobes of rough surfaces. Averaged over the samples of a pixel, the tree integrates soft
// shadows, blurred reflections and translucency, as Monte Carlo integration with 5 to 60 rays a
// pixel:
//   I = emission + ka Ia C + sum_lights mean_j shadow_j IL_j (kd C (N.L_j) + ks spec_j^n)
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

// Holds per-thread state: use one integrator per thread, or per tile.
class DistributedIntegrator {
public:
    // Its tiles share nothing.
    struct Shared {};
    static Shared prepare(const World&) { return {}; }

    explicit DistributedIntegrator(const World& world) : world_(world), feelers_(world) {}
    DistributedIntegrator(const World& world, const Shared&) : DistributedIntegrator(world) {}

    // The colour one sample sees along an eye ray, which may carry its pencil (pencil.h; null:
    // none), drawing its numbers from the stream. Counts every ray it traces, the eye ray
    // included.
    Color trace_eye_ray(const Ray& ray, const RayDifferential* pencil, SampleStream& stream,
                        RayStats& stats);
    // The same, given the eye ray's nearest hit, found with the rays of neighbouring pixels in
    // one packet (World::nearest_hits).
    Color trace_eye_ray(const Ray& ray, const std::optional<Hit>& hit,
                        const RayDifferential* pencil, SampleStream& stream, RayStats& stats);

    // The colour seen along a ray at the given depth (eye rays are 1) and weight (the product
    // of kr and kt above it), travelling through the given media. The pencil follows the ray
    // through mirrors and clear glass; a rough surface's spread drops it.
    Color trace(const Ray& ray, int depth, float weight, SampleStream& stream, RayStats& stats,
                const MediumStack& media = kVacuum, const RayDifferential* pencil = nullptr);

    // Records every ray it traces from now on into `recorder` (glint explain, output variables);
    // null stops.
    void record_into(RayRecorder* recorder) { recorder_ = recorder; }

private:
    // A ray traced and told to the recorder.
    Color trace_recorded(const Ray& ray, int depth, float weight, SampleStream& stream,
                         RayStats& stats, const MediumStack& media, const RayDifferential* pencil);
    template <bool kRecord>
    Color trace_ray(const Ray& ray, int depth, float weight, SampleStream& stream, RayStats& stats,
                    const MediumStack& media, const RayDifferential* pencil);
    // The colour along a ray whose nearest hit is `hit`.
    template <bool kRecord>
    Color shade(const Ray& ray, const std::optional<Hit>& hit, int depth, float weight,
                SampleStream& stream, RayStats& stats, const MediumStack& media,
                const RayDifferential* pencil);
    // color plus the local term of each light at the surface of c in turn, each area light and
    // emitting object sampled by its shadow rays. (By value: a colour added to through a
    // reference waits on its own stores.)
    template <bool kRecord>
    Color plus_direct_light(const struct SurfaceContext& c, const Ray& ray, SampleStream& stream,
                            RayStats& stats, Color color);

    const World& world_;
    ShadowFeelers feelers_;
    RayRecorder* recorder_ = nullptr;
};

}  // namespace glint
