// Progressive photon mapping (Jensen 1996; Knaus and Zwicker 2011): before each sample index's
// pass, photons leave the emitters (picked by power) and scatter through the scene by the
// adjoint BSDFs; each comes to rest in the pass's photon map at every surface that is not delta,
// but at the first surface a light reaches directly (that light comes by next-event estimation).
// The eye rays follow mirrors and clear glass (both parts of glass, a ray tree) to the surfaces
// that are not, take the lights there by next-event estimation, and the rest from the photons
// within a radius:
//   L = sum over photons within r of f(wo, wi_p) power_p / (pi r^2 photons emitted).
// The radius shrinks pass by pass as r_{i+1}^2 = r_i^2 (i + alpha) / (i + 1): each pass's image
// is biased by the blur of its radius, and their mean converges to the path tracer's image.
// Caustics, light focused by glass or mirrors onto diffuse surfaces, come out clean, even seen
// in a mirror, where the path tracer finds them only by chance.
#pragma once

#include <cstdint>
#include <memory>

#include "glint/math/color.h"
#include "glint/math/ray.h"
#include "glint/render/integrators/emitters.h"
#include "glint/render/integrators/medium_stack.h"
#include "glint/render/integrators/next_event.h"
#include "glint/render/integrators/photon_map.h"
#include "glint/render/integrators/ray_recorder.h"
#include "glint/render/ray_stats.h"
#include "glint/render/world.h"
#include "glint/sampling/sampler.h"

namespace glint {

class PhotonIntegrator {
public:
    struct Shared {
        Emitters emitters;
        NextEventLights lights;
        float first_radius;
        // The photon map of the pass being rendered (begin_pass) and the photons it emitted.
        std::shared_ptr<const PhotonMap> map;
        std::uint64_t emitted = 0;
    };
    static Shared prepare(const World& world);
    // Before the pass of sample index `sample`: traces its photons, in parallel, and builds
    // their map. Counts the photons' rays, the photons emitted and those stored.
    static void begin_pass(Shared& shared, const World& world, int sample, std::uint64_t seed,
                           RayStats& stats);
    // The gathering radius of the pass of sample index `sample`, from the first pass's.
    static float radius_of_pass(float first, float alpha, int sample);

    PhotonIntegrator(const World& world, const Shared& shared)
        : world_(world), shared_(shared), next_event_(world, shared.lights) {}

    Color trace_eye_ray(const Ray& ray, const RayDifferential* pencil, SampleStream& stream,
                        RayStats& stats);

    void record_into(RayRecorder* recorder) { recorder_ = recorder; }

private:
    // `throughput`: the product of the branch factors above, what this ray's colour counts for.
    template <bool kRecord>
    Color eye_ray(const Ray& ray, int depth, const MediumStack& media, Color throughput,
                  SampleStream& stream, const RayDifferential* pencil, RayStats& stats);
    // The photons' estimate of the light reflected at c, and how many were found.
    Color gather(const struct SurfaceContext& c, const Bsdf& bsdf, int& found) const;

    const World& world_;
    const Shared& shared_;
    NextEvent next_event_;
    RayRecorder* recorder_ = nullptr;
};

}  // namespace glint
