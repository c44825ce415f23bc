// `glint explain`'s recorder: each event of one sample's ray tree (ray_recorder.h), recorded into
// a RayTree with the numbers behind it.
#pragma once

#include <optional>
#include <vector>

#include "glint/accel/aggregate.h"
#include "glint/render/explain/ray_tree.h"
#include "glint/render/integrators/ray_recorder.h"
#include "glint/render/integrators/shadow_feelers.h"
#include "glint/render/integrators/surface_context.h"
#include "glint/render/world.h"
#include "glint/shading/light.h"

namespace glint {

// A light's name in the tree: "point light 0", "area light 1 (disk)", "emitting object 4
// (sphere)"; `light` indexes world.object_lights() when object_light, else world.lights().
std::string light_name(const World& world, std::size_t light, bool object_light);

class RayTreeRecorder final : public RayRecorder {
public:
    // Records into `tree`, whose nodes it appends (the first ray traced is the eye ray).
    RayTreeRecorder(const World& world, RayTree& tree);

    void begin_ray(const Ray& ray, int depth, float weight) override;
    void end_ray(Color value) override;
    void missed(Color background) override;
    void hit(const SurfaceContext& c, const Hit& hit) override;
    void fog(const FogEffect& effect, bool inside) override;
    void stop(StopReason reason) override;
    void light(std::size_t light, const SurfaceContext& c, const LightSample& ls, float time,
               Color term) override;
    void begin_light(std::size_t light, bool object_light) override;
    void light_sample(const SurfaceContext& c, const LightSample& ls, Point2 u, float time,
                      Color term) override;
    void end_light(Color value) override;
    void wavelength(float u, float nanometres) override;
    void branches(const SurfaceContext& c, const Branches& b, const MediumStack& media,
                  float wavelength, Vector3 incident, float weight) override;
    void branch(RayKind kind, Color factor, std::optional<Point2> lobe_u) override;
    void delta_part(RayKind kind, float k, float survival, bool traced) override;
    void blocked(RayKind kind, Point2 lobe_u) override;
    void path_vertex(const SurfaceContext& c, const PathVertexRecord& record) override;

private:
    RayNode& current() { return tree_.nodes[std::size_t(stack_.back())]; }
    BranchRecord& branch_of(RayKind kind);
    LightSampleRecord sample_record(std::size_t light, const SurfaceContext& c,
                                    const LightSample& ls, float time, Color term);

    const World& world_;
    RayTree& tree_;
    ShadowFeelers feelers_;        // its own: asking again costs the integrator's caches nothing
    std::vector<int> stack_;       // the rays being traced, innermost last
    std::optional<RayKind> next_;  // the kind of the branch traced next
};

}  // namespace glint
