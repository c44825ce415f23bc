// Amanatides' cone tracing (1984): one cone a pixel, as wide as the pixel's footprint, instead
// of one ray. Each sphere, plane, polygon, triangle and disk it meets reports the fraction of
// the cone's cross-section it covers; the pixel blends what the cone sees front to back by those
// fractions (anti-aliasing without more rays). A cone to an area light gives a soft shadow from
// the part of the light the occluders leave uncovered; reflected and refracted cones carry the
// spread the surface's curvature gives them (by the pencil of pencil.h) and widen with the
// surface's roughness (glossy reflection and translucency). Shapes without a cone test are seen
// by the cone's axis ray alone, covering all of it or nothing.
#pragma once

#include <cstdint>
#include <vector>

#include "glint/geometry/cone_coverage.h"
#include "glint/math/color.h"
#include "glint/math/ray.h"
#include "glint/render/integrators/medium_stack.h"
#include "glint/render/integrators/ray_recorder.h"
#include "glint/render/pencil.h"
#include "glint/render/ray_stats.h"
#include "glint/render/world.h"
#include "glint/sampling/sampler.h"

namespace glint {

class ConeIntegrator {
public:
    struct Shared {};
    static Shared prepare(const World&) { return {}; }

    // Keeps scratch lists of hits, one per depth of the cone tree: one integrator per thread.
    explicit ConeIntegrator(const World& world)
        : world_(world), hits_by_depth_(std::size_t(world.settings().max_depth) + 1) {}
    ConeIntegrator(const World& world, const Shared&) : ConeIntegrator(world) {}

    // The colour the cone around the eye ray sees; its spread is the pixel's (or a sample's
    // share of it) from the ray's pencil, which the render always gives a cone tracer.
    Color trace_eye_ray(const Ray& ray, const RayDifferential* pencil, SampleStream& stream,
                        RayStats& stats);

    // The colour a cone sees. `axis` is its real axis ray (leaving a surface, for secondary
    // cones), while the cone's apex may lie behind it (where the cone's sides meet); `self` is
    // the surface it leaves (seen by the axis ray only), kNone for an eye cone.
    static constexpr std::uint32_t kNone = ~std::uint32_t{0};
    Color trace(const RayCone& cone, const Ray& axis, std::uint32_t self, int depth, float weight,
                RayStats& stats, const MediumStack& media);

    // Cones are not rays: explain and the output variables, which follow rays, are refused for
    // the cone integrator before a render starts (settings_problem.h).
    void record_into(RayRecorder*) {}

private:
    struct ConeHit {
        ConeCoverage coverage;
        std::uint32_t primitive;
        std::optional<ShapeHit> axis_hit;  // for shapes seen by the axis ray
    };
    // The colour of the surface point hit, seen along `ray` from within the cone.
    // Every primitive of `mask` the cone meets beyond `start` along its axis and before `end`,
    // nearest first.
    void gather(const RayCone& cone, const Ray& axis, std::uint32_t self, float end,
                std::uint32_t mask, std::vector<ConeHit>& hits) const;
    Color shade(const RayCone& cone, const Ray& ray, const Hit& hit, int depth, float weight,
                RayStats& stats, const MediumStack& media);
    // The part of an area light a cone from the surface point to its centre sees, 1 - each
    // occluder's coverage in turn.
    float light_visible(const struct SurfaceContext& c, std::uint32_t self, Vector3 to_light,
                        float distance, float spread, float time, RayStats& stats);
    // The part of the footprint (of radius `width` across the light's direction) that a light
    // at a point, or a directional one, reaches: a cone from the light through it.
    float footprint_lit(const struct SurfaceContext& c, std::uint32_t self, Vector3 to_light,
                        float distance, float width, float time, RayStats& stats);
    // The part of a shadow cone that what casts shadows between its axis's origin and `end`
    // leaves uncovered, occluders taken as covering independent parts of it (Amanatides'
    // assumption).
    float uncovered_share(const RayCone& cone, const Ray& axis, std::uint32_t self, float end);

    const World& world_;
    std::vector<std::vector<ConeHit>> hits_by_depth_;  // sized once: trace() holds references
    std::vector<ConeHit> shadow_hits_;                 // shadow cones never nest
};

}  // namespace glint
