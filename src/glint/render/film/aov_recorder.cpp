#include "glint/render/film/aov_recorder.h"

#include <algorithm>

#include "glint/render/integrators/local_lighting.h"
#include "glint/shading/phong.h"

namespace glint {

void AovRecorder::begin_ray(const Ray& ray, int depth, float) {
    ++level_;
    if (level_ == 1) eye_ray_ = ray;
    sample_.tree_depth = std::max(sample_.tree_depth, depth);
}

void AovRecorder::end_ray(Color value) {
    // A branch of the eye ray returns: its share is its factor times its colour, as the
    // integrators add it.
    if (level_ == 2 && path_) {
        sample_.direct += branch_factor_ * child_emission_;
        sample_.indirect += branch_factor_ * value - branch_factor_ * child_emission_;
    } else if (level_ == 2) {
        Color& share = branch_kind_ == RayKind::reflected ? sample_.reflected : sample_.refracted;
        share += branch_factor_ * value;
    } else if (level_ == 1 && eye_fog_) {
        AovSample& s = sample_;
        const Color t = eye_fog_->transmittance;
        for (Color* part : {&s.emission, &s.ambient, &s.diffuse, &s.specular, &s.reflected,
                            &s.refracted, &s.direct, &s.indirect})
            *part *= t;
        s.fog = eye_fog_->added;
    }
    --level_;
}

void AovRecorder::missed(Color background) {
    if (at_eye()) sample_.emission = background;
    if (level_ == 2) child_emission_ = background;  // the sky, met by the scattered ray
}

void AovRecorder::fog(const FogEffect& effect, bool /*inside*/) {
    if (at_eye()) eye_fog_ = effect;
}

void AovRecorder::hit(const SurfaceContext& c, const Hit& hit) {
    if (!at_eye()) return;
    const Material& m = *c.material;
    AovSample& s = sample_;
    s.hit = true;
    s.depth = hit.shape_hit.t * length(eye_ray_.direction);
    s.position = c.sp.p;
    s.normal = to_vector(c.n);
    s.albedo = c.color;
    // The integrators skip uv where the material does not read it.
    if (wants_uv_)
        s.uv = uv_needed(m.color) == Uv::compute ? c.sp.uv : world_.surface_at(eye_ray_, hit).uv;
    s.object = std::int32_t(hit.primitive);
    s.material = std::int32_t(world_.material_index_at(hit));
    s.emission = c.emission;
    s.ambient = ambient_term(m, c.ambient_color, world_.ambient());
}

Color AovRecorder::diffuse_part(const SurfaceContext& c, const LightSample& ls, Color term) {
    const Material& m = *c.material;
    const Color diffuse = m.kd * diffuse_factor(c.n, ls.to_light, m.brilliance) * c.color;
    const Color highlight =
        m.ks > 0 ? m.ks * specular_factor(m.highlight, c.n, ls.to_light, c.to_viewer, m.shininess) *
                       highlight_color(m, c.color)
                 : Color{};
    const auto share = [&](float d, float h, float t) {
        return d + h > 0 ? t * (d / (d + h)) : 0.0f;
    };
    return {share(diffuse.r, highlight.r, term.r), share(diffuse.g, highlight.g, term.g),
            share(diffuse.b, highlight.b, term.b)};
}

void AovRecorder::light(std::size_t, const SurfaceContext& c, const LightSample& ls, float,
                        Color term) {
    if (!splits_lights()) return;
    const Color diffuse = diffuse_part(c, ls, term);
    sample_.diffuse += diffuse;
    sample_.specular += term - diffuse;
}

void AovRecorder::begin_light(std::size_t, bool) {
    light_diffuse_ = {};
    light_samples_ = 0;
}

void AovRecorder::light_sample(const SurfaceContext& c, const LightSample& ls, Point2, float,
                               Color term) {
    if (!splits_lights()) return;
    light_diffuse_ += diffuse_part(c, ls, term);
    ++light_samples_;
}

void AovRecorder::end_light(Color value) {
    if (!splits_lights() || light_samples_ == 0) return;
    const Color diffuse = light_diffuse_ / float(light_samples_);
    sample_.diffuse += diffuse;
    sample_.specular += value - diffuse;
}

void AovRecorder::branch(RayKind kind, Color factor, std::optional<Point2>) {
    if (!at_eye()) return;
    branch_kind_ = kind;
    branch_factor_ = factor;
}

void AovRecorder::path_vertex(const SurfaceContext&, const PathVertexRecord& record) {
    if (level_ == 2) child_emission_ = record.le * record.emission_weight;
    if (!at_eye()) return;
    path_ = true;
    sample_.emission = record.le * record.emission_weight;
    sample_.ambient = {};
    for (const NextEventRecord& next : record.next_events) sample_.direct += next.term;
    sample_.indirect += record.photon_term;  // 0 but for the photon integrator
}

}  // namespace glint
