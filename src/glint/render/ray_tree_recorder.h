// What the integrators tell `glint explain` as they trace one sample: each event of the ray tree,
// recorded into a RayTree with the numbers behind it. An integrator holds a pointer to one, null
// while rendering, so recording costs a test of that pointer per event and nothing else.
#pragma once

#include <optional>
#include <vector>

#include "glint/accel/aggregate.h"
#include "glint/render/ray_tree.h"
#include "glint/render/shadow_feelers.h"
#include "glint/render/surface_context.h"
#include "glint/render/world.h"
#include "glint/shading/light.h"

namespace glint {

class RayTreeRecorder {
public:
    // Records into `tree`, whose nodes it appends (the first ray traced is the eye ray).
    RayTreeRecorder(const World& world, RayTree& tree);

    // A ray is traced at this depth and weight; its colour is `value`. Calls between them are
    // about this ray. A ray begun after branch() is that branch's child.
    void begin_ray(const Ray& ray, int depth, float weight);
    void end_ray(Color value);

    void missed(Color background);
    void hit(const SurfaceContext& c, const Hit& hit);
    void stop(StopReason reason);  // max_depth: no branches

    // The local term, light by light: a light of one sample (a point light, or any light to
    // Whitted's tracer), or a light sampled n times between begin_light and end_light.
    void light(std::size_t light, const SurfaceContext& c, const LightSample& ls, float time,
               Color term);
    void begin_light(std::size_t light, bool object_light);
    void light_sample(const SurfaceContext& c, const LightSample& ls, Point2 u, float time,
                      Color term);
    void end_light(Color value);

    void wavelength(float u, float nanometres);
    // The surface's kr and kt (b, for a ray through `media` at that wavelength) and Snell's law
    // for the incident direction; branches whose weight falls below the minimum are cut here,
    // as the integrators cut them.
    void branches(const SurfaceContext& c, const Branches& b, const MediumStack& media,
                  float wavelength, Vector3 incident, float weight);
    // The branch of this kind is traced next, its colour multiplied by factor.
    void branch(RayKind kind, Color factor, std::optional<Point2> lobe_u = std::nullopt);
    // The branch's glossy lobe tipped it through the surface: not traced.
    void blocked(RayKind kind, Point2 lobe_u);

private:
    RayNode& current() { return tree_.nodes[std::size_t(stack_.back())]; }
    BranchRecord& branch_of(RayKind kind);
    LightSampleRecord sample_record(std::size_t light, const SurfaceContext& c,
                                    const LightSample& ls, float time, Color term);
    std::string light_name(std::size_t light, bool object_light) const;

    const World& world_;
    RayTree& tree_;
    ShadowFeelers feelers_;        // its own: asking again costs the integrator's caches nothing
    std::vector<int> stack_;       // the rays being traced, innermost last
    std::optional<RayKind> next_;  // the kind of the branch traced next
};

}  // namespace glint
