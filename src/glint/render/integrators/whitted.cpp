// The lecture notes' TraceRay: closest hit, the Phong terms with one shadow feeler per light,
// then the reflected and refracted rays, cut by depth and by weight.
#include "glint/render/integrators/whitted.h"

#include "glint/render/integrators/local_lighting.h"
#include "glint/render/integrators/media_marching.h"
#include "glint/render/integrators/ray_fog.h"
#include "glint/render/integrators/surface_context.h"

namespace glint {

Color WhittedIntegrator::trace_eye_ray(const Ray& ray, RayStats& stats,
                                       const RayDifferential* pencil) {
    stats.count(RayKind::primary);
    return trace(ray, 1, 1, stats, world_.eye_media(), pencil);
}

Color WhittedIntegrator::trace_eye_ray(const Ray& ray, const std::optional<Hit>& hit,
                                       const RayDifferential* pencil, SampleStream&,
                                       RayStats& stats) {
    stats.count(RayKind::primary);
    if (recorder_) [[unlikely]]
        return trace_recorded(ray, 1, 1, stats, world_.eye_media(), pencil);
    return shade<false>(ray, hit, 1, 1, stats, world_.eye_media(), pencil);
}

// shade() and what it calls are compiled twice: with kRecord, telling the recorder every event;
// without, the renderer's own code, with no trace of the recorder in it.

Color WhittedIntegrator::trace(const Ray& ray, int depth, float weight, RayStats& stats,
                               const MediumStack& media, const RayDifferential* pencil) {
    if (recorder_) [[unlikely]]
        return trace_recorded(ray, depth, weight, stats, media, pencil);
    return shade<false>(ray, world_.nearest_hit(ray), depth, weight, stats, media, pencil);
}

template <bool kRecord>
Color WhittedIntegrator::trace_ray(const Ray& ray, int depth, float weight, RayStats& stats,
                                   const MediumStack& media, const RayDifferential* pencil) {
    if constexpr (kRecord)
        return trace_recorded(ray, depth, weight, stats, media, pencil);
    else
        return shade<false>(ray, world_.nearest_hit(ray), depth, weight, stats, media, pencil);
}

// Out of line: the renderer's code stays as small as it was without a recorder.
[[gnu::noinline]] Color WhittedIntegrator::trace_recorded(const Ray& ray, int depth, float weight,
                                                          RayStats& stats, const MediumStack& media,
                                                          const RayDifferential* pencil) {
    recorder_->begin_ray(ray, depth, weight);
    const Color color =
        shade<true>(ray, world_.nearest_hit(ray), depth, weight, stats, media, pencil);
    recorder_->end_ray(color);
    return color;
}

template <bool kRecord>
Color WhittedIntegrator::shade(const Ray& ray, const std::optional<Hit>& hit, int depth,
                               float weight, RayStats& stats, const MediumStack& media,
                               const RayDifferential* pencil) {
    const RenderSettings& settings = world_.settings();
    const float length = hit ? hit->shape_hit.t : kInfinity;
    const std::optional<FogEffect> fog = with_media(world_, feelers_, media, ray, length, 0.5f,
                                                    stats, ray_fog(world_, ray, media, length));
    if (!hit) {
        const Color sky = world_.sky().radiance(ray.direction);
        if constexpr (kRecord) {
            recorder_->missed(sky);
            if (fog) recorder_->fog(*fog, media.size() > 0);
        }
        return through(fog, sky);
    }
    if (depth == 1) ++stats.primary_hits;

    const SurfaceContext c = surface_context(world_, ray, *hit, pencil);
    if constexpr (kRecord) {
        recorder_->hit(c, *hit);
        if (fog) recorder_->fog(*fog, media.size() > 0);
    }
    const Material& m = *c.material;
    Color color = c.emission + ambient_term(m, c.ambient_color, world_.ambient());
    const auto lights = world_.lights();
    for (std::size_t light = 0; light < lights.size(); ++light) {
        const LightSample ls = sample_light(lights[light], c.sp.p);
        const Color term = light_sample_term(feelers_, light, c, ls, ray.time, stats);
        if constexpr (kRecord) recorder_->light(light, c, ls, ray.time, term);
        color += term;
    }

    if (depth >= settings.max_depth) {
        if constexpr (kRecord) recorder_->stop(StopReason::max_depth);
        return through(fog, color);
    }
    const Branches b = branches_at(c, ray.direction, media, ray.wavelength);
    if constexpr (kRecord) recorder_->branches(c, b, media, ray.wavelength, ray.direction, weight);
    if (b.kr > 0 && weight * b.kr >= settings.min_weight) {
        stats.count(RayKind::reflected);
        const Ray r = spawn_from(world_, c, ray, normalize(reflect(ray.direction, c.n)));
        if constexpr (kRecord) recorder_->branch(RayKind::reflected, b.kr * b.reflect_filter);
        color += b.kr * b.reflect_filter *
                 trace_ray<kRecord>(r, depth + 1, weight * b.kr, stats, media,
                                    or_null(mirror_pencil(c, ray, pencil)));
    }
    if (b.kt > 0 && weight * b.kt >= settings.min_weight) {
        stats.count(RayKind::refracted);
        const Ray t = spawn_from(world_, c, ray, b.refracted);
        if constexpr (kRecord) recorder_->branch(RayKind::refracted, b.kt * b.filter);
        color += b.kt * b.filter *
                 trace_ray<kRecord>(t, depth + 1, weight * b.kt, stats, media_beyond(c, b, media),
                                    or_null(refraction_pencil(c, ray, pencil, b.eta, b.refracted)));
    }
    return through(fog, color);
}

}  // namespace glint
