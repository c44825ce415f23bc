// Distributed ray tracing: Whitted's recursion with every light sampled over its area.
#include "glint/render/integrators/distributed.h"

#include "glint/render/integrators/glossy_lobe.h"
#include "glint/render/integrators/local_lighting.h"
#include "glint/render/integrators/media_marching.h"
#include "glint/render/integrators/ray_fog.h"
#include "glint/render/integrators/surface_context.h"
#include "glint/render/integrators/wavelength_split.h"

namespace glint {

namespace {

// A lobe's numbers: a dimension of its own when the surface is rough, none for a mirror.
Point2 lobe_sample(float roughness, SampleStream& stream) {
    return roughness < kMirrorRoughness ? Point2{0, 0} : stream.next_2d();
}

// The lobe's numbers as drawn: none for a mirror.
std::optional<Point2> lobe_draw(float roughness, Point2 u) {
    if (roughness < kMirrorRoughness) return std::nullopt;
    return u;
}

}  // namespace

Color DistributedIntegrator::trace_eye_ray(const Ray& ray, const RayDifferential* pencil,
                                           SampleStream& stream, RayStats& stats) {
    stats.count(RayKind::primary);
    return trace(ray, 1, 1, stream, stats, world_.eye_media(), pencil);
}

Color DistributedIntegrator::trace_eye_ray(const Ray& ray, const std::optional<Hit>& hit,
                                           const RayDifferential* pencil, SampleStream& stream,
                                           RayStats& stats) {
    stats.count(RayKind::primary);
    if (recorder_) [[unlikely]]
        return trace_recorded(ray, 1, 1, stream, stats, world_.eye_media(), pencil);
    return shade<false>(ray, hit, 1, 1, stream, stats, world_.eye_media(), pencil);
}

// shade() and what it calls are compiled twice: with kRecord, telling the recorder every event;
// without, the renderer's own code, with no trace of the recorder in it.

Color DistributedIntegrator::trace(const Ray& ray, int depth, float weight, SampleStream& stream,
                                   RayStats& stats, const MediumStack& media,
                                   const RayDifferential* pencil) {
    if (recorder_) [[unlikely]]
        return trace_recorded(ray, depth, weight, stream, stats, media, pencil);
    return shade<false>(ray, world_.nearest_hit(ray), depth, weight, stream, stats, media, pencil);
}

template <bool kRecord>
Color DistributedIntegrator::trace_ray(const Ray& ray, int depth, float weight,
                                       SampleStream& stream, RayStats& stats,
                                       const MediumStack& media, const RayDifferential* pencil) {
    if constexpr (kRecord)
        return trace_recorded(ray, depth, weight, stream, stats, media, pencil);
    else
        return shade<false>(ray, world_.nearest_hit(ray), depth, weight, stream, stats, media,
                            pencil);
}

// Out of line: the renderer's code stays as small as it was without a recorder.
[[gnu::noinline]] Color DistributedIntegrator::trace_recorded(const Ray& ray, int depth,
                                                              float weight, SampleStream& stream,
                                                              RayStats& stats,
                                                              const MediumStack& media,
                                                              const RayDifferential* pencil) {
    recorder_->begin_ray(ray, depth, weight);
    const Color color =
        shade<true>(ray, world_.nearest_hit(ray), depth, weight, stream, stats, media, pencil);
    recorder_->end_ray(color);
    return color;
}

template <bool kRecord>
Color DistributedIntegrator::shade(const Ray& ray, const std::optional<Hit>& hit, int depth,
                                   float weight, SampleStream& stream, RayStats& stats,
                                   const MediumStack& media, const RayDifferential* pencil) {
    const RenderSettings& settings = world_.settings();
    const float length = hit ? hit->shape_hit.t : kInfinity;
    std::optional<FogEffect> fog = ray_fog(world_, ray, media, length);
    // Each sample draws where in its intervals the media are evaluated.
    if (media_around(world_, media)) [[unlikely]]
        fog = with_media(world_, feelers_, media, ray, length,
                         stream.get_1d(stream.next_dimension()), stats, fog);
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
    color = plus_direct_light<kRecord>(c, ray, stream, stats, color);

    if (depth >= settings.max_depth) {
        if constexpr (kRecord) recorder_->stop(StopReason::max_depth);
        return through(fog, color);
    }
    // A dispersive surface splits a ray that carries every wavelength: the refracted ray takes
    // the sample's wavelength, and what it brings back counts by that wavelength's colour.
    const WavelengthSplit split =
        split_wavelength(m, ray.wavelength, [&] { return stream.get_1d(kWavelengthDimension); });
    Ray parent = ray;
    parent.wavelength = split.wavelength;
    const Color spectral_weight = split.weight;
    if constexpr (kRecord)
        if (split.drawn) recorder_->wavelength(split.u, parent.wavelength);
    const Branches b = branches_at(c, ray.direction, media, parent.wavelength);
    if constexpr (kRecord)
        recorder_->branches(c, b, media, parent.wavelength, ray.direction, weight);
    if (b.kr > 0 && weight * b.kr >= settings.min_weight) {
        const Vector3 mirror = normalize(reflect(ray.direction, c.n));
        const Point2 u = lobe_sample(c.roughness, stream);
        const Vector3 d = spread_over_lobe(mirror, c.roughness, u, to_vector(c.ng), true);
        if (d != kBlockedByTheSurface) {
            stats.count(RayKind::reflected);
            const Ray r = spawn_from(world_, c, ray, d);
            if constexpr (kRecord)
                recorder_->branch(RayKind::reflected, b.kr * b.reflect_filter,
                                  lobe_draw(c.roughness, u));
            const auto r_pencil = c.roughness < kMirrorRoughness ? mirror_pencil(c, ray, pencil)
                                                                 : std::optional<RayDifferential>{};
            color += b.kr * b.reflect_filter *
                     trace_ray<kRecord>(r, depth + 1, weight * b.kr, stream, stats, media,
                                        or_null(r_pencil));
        } else if constexpr (kRecord) {
            recorder_->blocked(RayKind::reflected, u);
        }
    }
    if (b.kt > 0 && weight * b.kt >= settings.min_weight) {
        const Point2 u = lobe_sample(c.transmit_roughness, stream);
        const Vector3 d =
            spread_over_lobe(b.refracted, c.transmit_roughness, u, to_vector(c.ng), false);
        if (d != kBlockedByTheSurface) {
            stats.count(RayKind::refracted);
            const Ray t = spawn_from(world_, c, parent, d);
            const Color factor = b.kt * b.filter * spectral_weight;
            if constexpr (kRecord)
                recorder_->branch(RayKind::refracted, factor, lobe_draw(c.transmit_roughness, u));
            const auto t_pencil = c.transmit_roughness < kMirrorRoughness
                                      ? refraction_pencil(c, ray, pencil, b.eta, b.refracted)
                                      : std::optional<RayDifferential>{};
            color += factor * trace_ray<kRecord>(t, depth + 1, weight * b.kt, stream, stats,
                                                 media_beyond(c, b, media, parent.wavelength),
                                                 or_null(t_pencil));
        } else if constexpr (kRecord) {
            recorder_->blocked(RayKind::refracted, u);
        }
    }
    return through(fog, color);
}

template <bool kRecord>
Color DistributedIntegrator::plus_direct_light(const SurfaceContext& c, const Ray& ray,
                                               SampleStream& stream, RayStats& stats, Color color) {
    const auto lights = world_.lights();
    for (std::size_t light = 0; light < lights.size(); ++light) {
        if (!is_area_light(lights[light])) {
            const LightSample ls = sample_light(lights[light], c.sp.p);
            const Color term = light_sample_term(feelers_, light, c, ls, ray.time, stats);
            if constexpr (kRecord) recorder_->light(light, c, ls, ray.time, term);
            color += term;
            continue;
        }
        // n shadow rays, stratified together with those of the pixel's other samples.
        const int own = std::get<AreaLight>(lights[light]).shadow_rays;
        const auto n = std::uint32_t(own > 0 ? own : world_.settings().shadow_rays);
        const std::uint32_t dimension = stream.next_dimension();
        if constexpr (kRecord) recorder_->begin_light(light, false);
        Color light_sum;
        for (std::uint32_t j = 0; j < n; ++j) {
            const Point2 u = stream.get_2d(dimension, j, n);
            const LightSample ls = sample_light(lights[light], c.sp.p, u);
            const Color term = light_sample_term(feelers_, light, c, ls, ray.time, stats);
            if constexpr (kRecord) recorder_->light_sample(c, ls, u, ray.time, term);
            light_sum += term;
        }
        const Color mean = light_sum / float(n);
        if constexpr (kRecord) recorder_->end_light(mean);
        color += mean;
    }
    const auto n = std::uint32_t(world_.settings().shadow_rays);
    const auto object_lights = world_.object_lights();
    for (std::size_t index = 0; index < object_lights.size(); ++index) {
        const std::uint32_t dimension = stream.next_dimension();
        if constexpr (kRecord) recorder_->begin_light(index, true);
        Color light_sum;
        for (std::uint32_t j = 0; j < n; ++j) {
            const Point2 u = stream.get_2d(dimension, j, n);
            const LightSample ls = sample_light(object_lights[index], c.sp.p, u);
            const Color term =
                light_sample_term(feelers_, ShadowFeelers::kNoLight, c, ls, ray.time, stats);
            if constexpr (kRecord) recorder_->light_sample(c, ls, u, ray.time, term);
            light_sum += term;
        }
        const Color mean = light_sum / float(n);
        if constexpr (kRecord) recorder_->end_light(mean);
        color += mean;
    }
    return color;
}

}  // namespace glint
