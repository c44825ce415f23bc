// Light tracing, the notes' "backward ray tracing" (Arvo 1986; Dutre, Lafortune and Willems
// 1993): particles leave the lights, picked by power, and scatter through the scene by the
// materials' BSDFs; every surface a particle reaches that is not a mirror or clear glass is
// connected to the eye by a shadow ray, and what it sends that way lands on the film where the
// eye sees the surface. Most particles never reach the eye, as the notes say: the render counts
// them. Each sample of a pixel sends one particle; its eye ray adds what no particle can bring:
// emitters and the sky seen directly or through mirrors and clear glass. Surfaces seen only
// through mirrors or glass stay black (no particle can be joined to the eye through them): the
// price of tracing light forwards.
#pragma once

#include <functional>

#include "glint/math/color.h"
#include "glint/math/ray.h"
#include "glint/render/film/splat_film.h"
#include "glint/render/integrators/emitters.h"
#include "glint/render/integrators/ray_recorder.h"
#include "glint/render/integrators/shadow_feelers.h"
#include "glint/render/ray_stats.h"
#include "glint/render/world.h"
#include "glint/sampling/sampler.h"

namespace glint {

// One contribution of a particle to the film, as it is splatted: for `glint explain`.
struct ParticleSplat {
    std::size_t emitter = 0;  // of the Emitters' list, which sent it
    int bounces = 0;          // surfaces it met before this one
    std::uint32_t object = 0;
    Point3 point;
    Point2 film;  // where it lands, in pixels
    Color value;  // what it adds there, before the filter
};
using ParticleObserver = std::function<void(const ParticleSplat&)>;

class LightIntegrator {
public:
    // The emitters by power.
    struct Shared {
        Emitters emitters;
    };
    static Shared prepare(const World& world) { return {Emitters(world)}; }

    LightIntegrator(const World& world, const Shared& shared)
        : world_(world), shared_(shared), feelers_(world, /*opaque=*/true) {}

    // What the eye sees of emitters and the sky, straight or through mirrors and clear glass.
    Color trace_eye_ray(const Ray& ray, const RayDifferential* pencil, SampleStream& stream,
                        RayStats& stats);
    // One particle, its numbers from the sample's stream after the eye ray's; each surface it
    // reaches adds its share to `film`.
    void trace_particle(SampleStream& stream, SplatFilm& film, RayStats& stats);

    void record_into(RayRecorder* recorder) { recorder_ = recorder; }
    // Tells `observer` of each contribution trace_particle splats.
    void observe_particles(const ParticleObserver* observer) { observer_ = observer; }

private:
    template <bool kRecord>
    Color eye_ray(const Ray& ray, int depth, const MediumStack& media, SampleStream& stream,
                  const RayDifferential* pencil, RayStats& stats);
    const World& world_;
    const Shared& shared_;
    ShadowFeelers feelers_;
    RayRecorder* recorder_ = nullptr;
    const ParticleObserver* observer_ = nullptr;
};

}  // namespace glint
