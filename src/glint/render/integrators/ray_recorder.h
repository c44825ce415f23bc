// What the integrators tell a recorder as they trace one sample: each event of the ray tree, in
// order. An integrator holds a pointer to one, null while rendering: its shade() is compiled a
// second time with the calls in, so a render without a recorder runs the code it ran before.
// A recorder overrides the events it needs: the ray tree of `glint explain` (RayTreeRecorder)
// takes them all, the output variables of a render (AovRecorder) a few at the eye ray.
#pragma once

#include <cstddef>
#include <optional>

#include "glint/accel/aggregate.h"
#include "glint/math/color.h"
#include "glint/math/ray.h"
#include "glint/render/explain/ray_tree.h"
#include "glint/render/integrators/medium_stack.h"
#include "glint/render/integrators/surface_context.h"
#include "glint/render/ray_stats.h"
#include "glint/shading/fog.h"
#include "glint/shading/light.h"

namespace glint {

class RayRecorder {
public:
    virtual ~RayRecorder() = default;

    // A ray is traced at this depth and weight; its colour is `value`. Calls between them are
    // about this ray. A ray begun after branch() is that branch's child.
    virtual void begin_ray(const Ray& ray, int depth, float weight) = 0;
    virtual void end_ray(Color value) = 0;

    virtual void missed(Color background) = 0;
    virtual void hit(const SurfaceContext& c, const Hit& hit) = 0;
    // The fog between the ray's origin and its end, which acts on all the ray brings back, or
    // inside an object (`inside`) its interior fade; after missed() or hit(), before the ray's
    // terms.
    virtual void fog(const FogEffect&, bool /*inside*/) {}
    virtual void stop(StopReason) {}  // max_depth: no branches

    // The local term, light by light: a light of one sample (a point light, or any light to
    // Whitted's tracer), or a light sampled n times between begin_light and end_light.
    virtual void light(std::size_t light, const SurfaceContext& c, const LightSample& ls,
                       float time, Color term) = 0;
    virtual void begin_light(std::size_t light, bool object_light) = 0;
    virtual void light_sample(const SurfaceContext& c, const LightSample& ls, Point2 u, float time,
                              Color term) = 0;
    virtual void end_light(Color value) = 0;

    virtual void wavelength(float /*u*/, float /*nanometres*/) {}
    // The surface's kr and kt (b, for a ray through `media` at that wavelength) and Snell's law
    // for the incident direction; branches whose weight falls below the minimum are cut here,
    // as the integrators cut them.
    virtual void branches(const SurfaceContext&, const Branches&, const MediumStack&,
                          float /*wavelength*/, Vector3 /*incident*/, float /*weight*/) {}
    // The branch of this kind is traced next, its colour multiplied by factor.
    virtual void branch(RayKind kind, Color factor,
                        std::optional<Point2> lobe_u = std::nullopt) = 0;
    // The photon integrator's eye ray meets a delta part of weight k (its largest channel):
    // Russian roulette traces it with probability `survival` (1: always), and did or not; a
    // traced one's branch() follows.
    virtual void delta_part(RayKind, float /*k*/, float /*survival*/, bool /*traced*/) {}
    // The branch's glossy lobe tipped it through the surface: not traced.
    virtual void blocked(RayKind, Point2 /*lobe_u*/) {}

    // The path tracer's numbers at the surface point hit: in the place of the local term, its
    // weighted emission and the light it sampled (record.term), before it scatters.
    virtual void path_vertex(const SurfaceContext&, const PathVertexRecord&) {}

protected:
    RayRecorder() = default;
    RayRecorder(const RayRecorder&) = default;
    RayRecorder& operator=(const RayRecorder&) = default;
};

}  // namespace glint
