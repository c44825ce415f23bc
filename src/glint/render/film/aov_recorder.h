// The recorder behind a render's output variables (aov.h): of the events of a sample's ray tree
// it keeps what the eye ray hit, the eye node's terms (emission, ambient, each light's diffuse and
// highlight parts, the reflected and refracted branches with their factors), and the tree's
// depth. It allocates nothing, so the render loop can keep one per tile.
#pragma once

#include <optional>

#include "glint/render/film/aov.h"
#include "glint/render/integrators/ray_recorder.h"
#include "glint/render/world.h"

namespace glint {

class AovRecorder final : public RayRecorder {
public:
    // Works out only what `wanted` needs beyond what the integrator hands it (uv where the
    // material reads none, the lights' diffuse and highlight parts).
    AovRecorder(const World& world, AovSet wanted)
        : world_(world),
          wants_uv_(wanted.has(Aov::uv)),
          wants_split_(wanted.has(Aov::diffuse) || wanted.has(Aov::specular)) {}

    // Forgets the last sample: call before tracing each eye ray.
    void start() {
        sample_ = {};
        level_ = 0;
        path_ = false;
        child_emission_ = {};
        eye_fog_.reset();
    }
    // What the sample's events told, once its eye ray has returned.
    const AovSample& sample() const { return sample_; }

    void begin_ray(const Ray& ray, int depth, float weight) override;
    void end_ray(Color value) override;
    void missed(Color background) override;
    void hit(const SurfaceContext& c, const Hit& hit) override;
    // The eye ray's fog: once it returns, its parts are seen through it and the fog's own light
    // is a part of its own.
    void fog(const FogEffect& effect, bool inside) override;
    void light(std::size_t light, const SurfaceContext& c, const LightSample& ls, float time,
               Color term) override;
    void begin_light(std::size_t light, bool object_light) override;
    void light_sample(const SurfaceContext& c, const LightSample& ls, Point2 u, float time,
                      Color term) override;
    void end_light(Color value) override;
    void branch(RayKind kind, Color factor, std::optional<Point2> lobe_u) override;
    // The path tracer's eye vertex: its weighted emission, and the light it sampled, which is
    // direct; of what its scattered ray brings back, the emission that ray meets is direct too,
    // the rest indirect.
    void path_vertex(const SurfaceContext& c, const PathVertexRecord& record) override;

private:
    // The diffuse part of a light sample's term: the term split in the ratio of its unshadowed
    // diffuse and highlight parts, channel by channel.
    static Color diffuse_part(const SurfaceContext& c, const LightSample& ls, Color term);
    bool at_eye() const { return level_ == 1; }
    bool splits_lights() const { return wants_split_ && at_eye(); }

    const World& world_;
    bool wants_uv_, wants_split_;
    AovSample sample_;
    int level_ = 0;  // the depth of the ray being traced, 0 before and after the eye ray
    Ray eye_ray_;
    Color light_diffuse_;  // the diffuse parts of the light being sampled, summed
    int light_samples_ = 0;
    Color branch_factor_;  // of the eye ray's branch traced next
    RayKind branch_kind_ = RayKind::reflected;
    bool path_ = false;     // the eye ray's vertex was a path tracer's
    Color child_emission_;  // the weighted emission met by the eye vertex's scattered ray
    std::optional<FogEffect> eye_fog_;
};

}  // namespace glint
