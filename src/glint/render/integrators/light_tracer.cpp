// Light tracing: particles from the lights, each surface they reach joined to the eye; and the
// eye rays' share, the emitters seen straight or through delta surfaces.
#include "glint/render/integrators/light_tracer.h"

#include <algorithm>
#include <vector>

#include "glint/render/film/film.h"
#include "glint/render/integrators/path.h"
#include "glint/render/integrators/ray_fog.h"
#include "glint/render/integrators/roulette.h"
#include "glint/render/integrators/surface_context.h"
#include "glint/render/integrators/wavelength_split.h"
#include "glint/shading/bsdf.h"

namespace glint {

Color LightIntegrator::trace_eye_ray(const Ray& ray, const RayDifferential* pencil,
                                     SampleStream& stream, RayStats& stats) {
    stats.count(RayKind::primary);
    if (recorder_) [[unlikely]]
        return eye_ray<true>(ray, 1, world_.eye_media(), stream, pencil, stats);
    return eye_ray<false>(ray, 1, world_.eye_media(), stream, pencil, stats);
}

template <bool kRecord>
Color LightIntegrator::eye_ray(const Ray& ray, int depth, const MediumStack& media,
                               SampleStream& stream, const RayDifferential* pencil,
                               RayStats& stats) {
    const RenderSettings& settings = world_.settings();
    if constexpr (kRecord) recorder_->begin_ray(ray, depth, 1);
    const auto hit = world_.nearest_hit(ray);
    // Inside an object that fades, all the ray brings back fades on its way.
    const std::optional<FogEffect> fade = interior_fade(media, hit ? hit->shape_hit.t : kInfinity);
    if (!hit) {
        const Color sky = world_.sky().radiance(ray.direction);
        if constexpr (kRecord) {
            recorder_->missed(sky);
            if (fade) recorder_->fog(*fade, true);
            recorder_->end_ray(through(fade, sky));
        }
        return through(fade, sky);
    }
    if (depth == 1) ++stats.primary_hits;
    const SurfaceContext c = surface_context(world_, ray, *hit, pencil);
    if constexpr (kRecord) {
        recorder_->hit(c, *hit);
        if (fade) recorder_->fog(*fade, true);
    }
    PathVertexRecord record;
    record.le = c.emission;
    Color color = c.emission;
    const auto end = [&](StopReason reason) {
        color = through(fade, color);
        if constexpr (kRecord) {
            recorder_->path_vertex(c, record);
            if (reason != StopReason::none) recorder_->stop(reason);
            recorder_->end_ray(color);
        }
        return color;
    };
    if (depth > settings.max_depth) return end(StopReason::max_depth);
    // Only a delta part is followed: the light a smooth part reflects towards the eye comes by
    // the particles. Picking it with its probability keeps the estimate of the delta part's
    // share exact on average.
    // A dispersive surface splits the ray as in the path tracer.
    const Material& m = *c.material;
    const WavelengthSplit split =
        split_wavelength(m, ray.wavelength, [&] { return stream.get_1d(kWavelengthDimension); });
    const float wavelength = split.wavelength;
    const Color spectral_weight = split.weight;
    if constexpr (kRecord)
        if (split.drawn) recorder_->wavelength(split.u, wavelength);
    const SnellIndices eta = snell_indices(c, media, wavelength);
    const Bsdf bsdf(bsdf_inputs(c, eta));
    const float u_lobe = stream.next_1d();
    const Point2 u = stream.next_2d();
    const std::optional<BsdfSample> s = bsdf.sample(u_lobe, u);
    if (!s || !s->delta) return end(StopReason::none);
    if constexpr (kRecord) {
        record.scattered = true;
        record.lobe = s->transmitted ? "transmit" : "reflect";
        record.wi = s->wi;
        record.scatter_pdf = s->pdf;
        record.delta = true;
        record.weight = s->weight;
    }
    const RayKind kind = s->transmitted ? RayKind::refracted : RayKind::reflected;
    stats.count(kind);
    Ray next = world_.spawn_ray(c.sp.p, c.ng, s->wi, c.sp.error, ray.time);
    next.wavelength = s->transmitted ? wavelength : ray.wavelength;
    const Color factor = s->transmitted ? s->weight * spectral_weight : s->weight;
    MediumStack beyond = media;
    if (s->transmitted)
        beyond = c.entering ? media.entered(c.primitive, &m, ior_at(m, wavelength))
                            : media.left(c.primitive, &m);
    if constexpr (kRecord) {
        recorder_->path_vertex(c, record);
        recorder_->branch(kind, factor, std::nullopt);
    }
    const auto next_pencil = s->transmitted
                                 ? refraction_pencil(c, ray, pencil, eta.n1 / eta.n2, s->wi)
                                 : mirror_pencil(c, ray, pencil);
    color = through(fade, color + factor * eye_ray<kRecord>(next, depth + 1, beyond, stream,
                                                            or_null(next_pencil), stats));
    if constexpr (kRecord) recorder_->end_ray(color);
    return color;
}

void LightIntegrator::trace_particle(SampleStream& stream, SplatFilm& film, RayStats& stats) {
    if (!shared_.emitters.any()) return;
    const RenderSettings& settings = world_.settings();
    const Camera& camera = world_.camera();
    ++stats.particles;
    const float u_pick = stream.next_1d();
    const Point2 u_position = stream.next_2d(), u_direction = stream.next_2d();
    const EmittedParticle e = shared_.emitters.emit(u_pick, u_position, u_direction);
    Color beta = e.power;
    if (is_black(beta)) return;
    // At the moment its sample's eye ray was traced, so that what moves blurs alike.
    const float time = camera.has_shutter() ? camera.shutter_time(stream.get_1d(kTimeDimension))
                                            : camera.shutter_open();
    Ray ray = world_.spawn_ray(e.origin, Normal3(e.direction), e.direction, 0, time);
    MediumStack media;
    float wavelength = 0;
    Color throughput{1, 1, 1};  // the product of the weights, for Russian roulette
    bool seen = false;
    for (int depth = 1; depth <= settings.max_depth; ++depth) {
        const auto hit = world_.nearest_hit(ray);
        stats.count(RayKind::particle);
        if (!hit) break;
        if (const auto fade = interior_fade(media, hit->shape_hit.t)) {
            beta *= fade->transmittance;
            throughput *= fade->transmittance;
        }
        const SurfaceContext c = surface_context(world_, ray, *hit);
        const Material& m = *c.material;
        const WavelengthSplit split =
            split_wavelength(m, wavelength, [&] { return stream.next_1d(); });
        wavelength = split.wavelength;
        const Color spectral_weight = split.weight;
        const Bsdf bsdf(bsdf_inputs(c, snell_indices(c, media, wavelength)),
                        TransportMode::importance);
        // Joined to the eye through a point of its lens.
        const Point2 u_lens = stream.next_2d();
        if (bsdf.has_smooth_part()) {
            const auto to_eye = camera.connect(c.sp.p, u_lens, ray.time);
            if (to_eye && to_eye->film.x >= 0 && to_eye->film.x < float(settings.width) &&
                to_eye->film.y >= 0 && to_eye->film.y < float(settings.height)) {
                const Color f = bsdf.eval(to_eye->to_camera);
                if (!is_black(f)) {
                    const Normal3 side = dot(to_eye->to_camera, c.ng) >= 0 ? c.ng : -c.ng;
                    const Ray feeler =
                        world_.spawn_ray(c.sp.p, side, to_eye->to_camera, c.sp.error, ray.time);
                    const float reach =
                        distance(feeler.origin, to_eye->lens) * (1 - kRelativeRayEpsilon);
                    stats.count(RayKind::shadow);
                    if (!world_.occluded(feeler, {0, reach}, kVisibleToCameraRays)) {
                        const float cosine = std::abs(dot(to_vector(c.n), to_eye->to_camera));
                        const Color value = beta * f * (cosine * to_eye->importance);
                        if (is_valid_sample(value)) {
                            film.splat(to_eye->film, value);
                            seen = true;
                            if (observer_) [[unlikely]]
                                (*observer_)({shared_.emitters.picked(u_pick), depth - 1,
                                              c.primitive, c.sp.p, to_eye->film, value});
                        }
                    }
                }
            }
        }
        if (depth == settings.max_depth) break;
        const float u_lobe = stream.next_1d();
        const Point2 u = stream.next_2d();
        const std::optional<BsdfSample> s = bsdf.sample(u_lobe, u);
        if (!s) break;
        Color factor = s->weight;
        if (s->transmitted) factor *= spectral_weight;
        throughput *= factor;
        if (const float p = survival_probability(throughput, depth); p < 1) {
            if (stream.next_1d() >= p) break;
            factor = factor / p;
            throughput = throughput / p;
        }
        beta *= factor;
        if (s->transmitted) {
            const float ior = ior_at(m, wavelength);
            media = c.entering ? media.entered(c.primitive, &m, ior) : media.left(c.primitive, &m);
        }
        ray = world_.spawn_ray(c.sp.p, c.ng, s->wi, c.sp.error, ray.time);
        ray.wavelength = wavelength;
    }
    if (seen) ++stats.particles_seen;
}

}  // namespace glint
