// Unidirectional path tracing (Kajiya 1986): from each eye ray one path scatters through the
// scene by the materials' BSDFs, and at each vertex next-event estimation sends a shadow ray to
// one light, picked in proportion to its power. A light's radiance reached both ways (an
// emitting object, by the shadow ray and by the scattered ray that hits it) is weighed by
// multiple importance sampling with the power heuristic (Veach and Guibas 1995); Russian
// roulette ends paths whose throughput has fallen (after the third bounce). It computes what
// Whitted's and Cook's tracers leave to the ambient term: light that surfaces reflect onto one
// another, diffusely too (colour bleeding).
//   L(x, wo) = Le(x, wo) + integral f(x, wo, wi) L(x', -wi) |cos theta_i| dwi
#pragma once

#include <cstdint>
#include <optional>

#include "glint/math/color.h"
#include "glint/math/ray.h"
#include "glint/render/explain/ray_tree.h"
#include "glint/render/integrators/medium_stack.h"
#include "glint/render/integrators/next_event.h"
#include "glint/render/integrators/ray_recorder.h"
#include "glint/render/ray_stats.h"
#include "glint/render/world.h"
#include "glint/sampling/sampler.h"
#include "glint/shading/bsdf.h"

namespace glint {

class PathIntegrator {
public:
    // The lights by power, for next-event estimation.
    struct Shared {
        NextEventLights lights;
    };
    static Shared prepare(const World& world) { return {NextEventLights(world)}; }

    PathIntegrator(const World& world, const Shared& shared)
        : world_(world), next_event_(world, shared.lights) {}

    // The radiance one sample's path brings back along the eye ray. Counts every ray it traces.
    Color trace_eye_ray(const Ray& ray, const RayDifferential* pencil, SampleStream& stream,
                        RayStats& stats);
    // The same, given the eye ray's nearest hit, found with the rays of neighbouring pixels in
    // one packet (World::nearest_hits).
    Color trace_eye_ray(const Ray& ray, const std::optional<Hit>& hit,
                        const RayDifferential* pencil, SampleStream& stream, RayStats& stats);

    void record_into(RayRecorder* recorder) { recorder_ = recorder; }

private:
    // What the path has been through: the throughput so far (for Russian roulette) and what
    // the vertex it left from tells the next one (whether it scattered by a delta part, and the
    // density of its scattered direction, for the weight of an emitter hit).
    struct PathState {
        int depth = 1;              // of the ray being traced: eye rays are 1
        Color throughput{1, 1, 1};  // the product of the weights before this ray
        bool after_delta = true;    // the eye, or a mirror or clear refraction, sent it
        float bsdf_pdf = 0;         // per steradian, when not after_delta
        Point3 from;                // where it left from
        MediumStack media;          // the media it travels in
        // Its pencil (pencil.h): from the eye, kept through mirrors and clear glass only.
        std::optional<RayDifferential> pencil;
    };

    // Along a ray whose nearest hit is `hit`.
    template <bool kRecord>
    Color radiance(const Ray& ray, const std::optional<Hit>& hit, PathState path,
                   SampleStream& stream, RayStats& stats);
    // The weight an emitting surface the path hit counts its emission with, weighed against
    // the shadow rays that could have found it, and the densities weighed.
    struct EmissionWeight {
        float weight = 1, bsdf_pdf = 0, light_pdf = 0;
    };
    EmissionWeight emission_weight(const struct SurfaceContext& c, const PathState& path) const;

    const World& world_;
    NextEvent next_event_;
    RayRecorder* recorder_ = nullptr;
};

}  // namespace glint
