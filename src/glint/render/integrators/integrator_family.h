// The one place that turns an integrator's kind (scene/integrators.h, its table) into its class:
// the render loop, `glint explain` and the output variables all go through with_integrator,
// which hands the class to a generic lambda as a template argument, so that a render calls its
// integrator without a virtual call per ray.
//
// An integrator is a class with
//   using Shared = ...;                                // what its tiles share, built once
//   static Shared prepare(const World&);               // before the first pass
//   Integrator(const World&, const Shared&);           // one per tile: per-thread caches
//   Color trace_eye_ray(const Ray&, const RayDifferential* pencil, SampleStream&, RayStats&);
//   void record_into(RayRecorder*);                    // explain, the output variables
// and, when it has or needs them, the hooks the render loop then calls:
//   Color trace_eye_ray(const Ray&, const std::optional<Hit>&, const RayDifferential* pencil,
//                       SampleStream&, RayStats&);
//       the same, given the eye ray's nearest hit: eye rays are then traced in packets
//   void draw_tile(const Tile&, FilmTile&, RayStats&);
//       instead of tracing eye rays: draws the whole tile, once (beam tracing)
//   static void begin_pass(Shared&, const World&, int sample, seed, RayStats&);
//       before the pass of one sample index (its pass_size in the table is 1): photon maps
//   void trace_particle(SampleStream&, SplatFilm&, RayStats&);
//       after each eye sample: particles that land anywhere on the film
#pragma once

#include "glint/render/integrators/beam_tracer.h"
#include "glint/render/integrators/cone_tracer.h"
#include "glint/render/integrators/distributed.h"
#include "glint/render/integrators/light_tracer.h"
#include "glint/render/integrators/path.h"
#include "glint/render/integrators/photon_mapper.h"
#include "glint/render/integrators/whitted.h"
#include "glint/scene/integrators.h"

namespace glint {

// f.template operator()<Integrator>() for the class of `kind`.
template <class F>
decltype(auto) with_integrator(IntegratorKind kind, F&& f) {
    switch (kind) {
        case IntegratorKind::whitted:
            return f.template operator()<WhittedIntegrator>();
        case IntegratorKind::distributed:
            return f.template operator()<DistributedIntegrator>();
        case IntegratorKind::path:
            return f.template operator()<PathIntegrator>();
        case IntegratorKind::light:
            return f.template operator()<LightIntegrator>();
        case IntegratorKind::photon:
            return f.template operator()<PhotonIntegrator>();
        case IntegratorKind::cone:
            return f.template operator()<ConeIntegrator>();
        case IntegratorKind::beam:
            return f.template operator()<BeamIntegrator>();
    }
    __builtin_unreachable();  // every kind has a case: -Wswitch names one that has not
}

}  // namespace glint
