// Path tracing: a recursion along one path (each ray's radiance is its vertex's emitted and
// direct light plus the scattered ray's, times the BSDF's weight), so that `glint explain`
// records it as the ray tree it is, a tree of one branch.
#include "glint/render/integrators/path.h"

#include <algorithm>
#include <vector>

#include "glint/render/integrators/ray_fog.h"
#include "glint/render/integrators/roulette.h"
#include "glint/render/integrators/surface_context.h"
#include "glint/render/integrators/wavelength_split.h"

namespace glint {

namespace {

// The kind of ray a part of the BSDF sends.
RayKind kind_of(BsdfLobe lobe) {
    switch (lobe) {
        case BsdfLobe::diffuse:
        case BsdfLobe::highlight:
            return RayKind::diffuse;
        case BsdfLobe::reflect:
            return RayKind::reflected;
        case BsdfLobe::transmit:
            return RayKind::refracted;
    }
    return RayKind::diffuse;
}

}  // namespace

Color PathIntegrator::trace_eye_ray(const Ray& ray, const RayDifferential* pencil,
                                    SampleStream& stream, RayStats& stats) {
    return trace_eye_ray(ray, world_.nearest_hit(ray), pencil, stream, stats);
}

Color PathIntegrator::trace_eye_ray(const Ray& ray, const std::optional<Hit>& hit,
                                    const RayDifferential* pencil, SampleStream& stream,
                                    RayStats& stats) {
    stats.count(RayKind::primary);
    PathState path;
    path.media = world_.eye_media();
    if (pencil) path.pencil = *pencil;
    if (recorder_) [[unlikely]]
        return radiance<true>(ray, hit, path, stream, stats);
    return radiance<false>(ray, hit, path, stream, stats);
}

PathIntegrator::EmissionWeight PathIntegrator::emission_weight(const SurfaceContext& c,
                                                               const PathState& path) const {
    // Seen by the eye, in a mirror or through clear glass: no shadow ray could have found it.
    if (path.after_delta) return {};
    // An area light's face, or an object that glows without lighting: its light comes from
    // the light itself, or from nowhere, as in the other integrators.
    if (!world_.lights_scene(c.primitive)) return {0, 0, 0};
    const std::int32_t index = world_.object_light_index(c.primitive);
    // No shadow ray aims at it: the scattered rays that find it are all its light.
    if (index < 0 || !next_event_.any()) return {1, path.bsdf_pdf, 0};
    const float light_pdf =
        next_event_.object_light_pdf(std::size_t(index), path.from, c.sp.p, c.sp.normal);
    return {power_heuristic(path.bsdf_pdf, light_pdf), path.bsdf_pdf, light_pdf};
}

template <bool kRecord>
Color PathIntegrator::radiance(const Ray& ray, const std::optional<Hit>& hit, PathState path,
                               SampleStream& stream, RayStats& stats) {
    const RenderSettings& settings = world_.settings();
    if constexpr (kRecord) recorder_->begin_ray(ray, path.depth, 1);
    // Inside an object that fades, all the ray brings back fades on its way.
    const std::optional<FogEffect> fade =
        interior_fade(path.media, hit ? hit->shape_hit.t : kInfinity);
    if (!hit) {
        // The sky, weighed against the shadow rays that could have found it.
        const Color le = world_.sky().radiance(ray.direction);
        const float weight =
            path.after_delta ? 1
                             : power_heuristic(path.bsdf_pdf, next_event_.sky_pdf(ray.direction));
        const Color sky = le * weight;
        if constexpr (kRecord) {
            recorder_->missed(sky);
            if (fade) recorder_->fog(*fade, true);
            recorder_->end_ray(through(fade, sky));
        }
        return through(fade, sky);
    }
    if (path.depth == 1) ++stats.primary_hits;
    const SurfaceContext c = surface_context(world_, ray, *hit, or_null(path.pencil));
    if constexpr (kRecord) {
        recorder_->hit(c, *hit);
        if (fade) recorder_->fog(*fade, true);
    }
    if (fade) path.throughput *= fade->transmittance;
    const Material& m = *c.material;
    PathVertexRecord record;
    Color color;
    if (!is_black(c.emission)) {
        const EmissionWeight e = emission_weight(c, path);
        color = c.emission * e.weight;
        record.le = c.emission;
        record.emission_weight = e.weight;
        record.emission_bsdf_pdf = e.bsdf_pdf;
        record.emission_light_pdf = e.light_pdf;
    }
    // The end of the path: tells the recorder what the vertex did, and returns.
    const auto end = [&](StopReason reason) {
        color = through(fade, color);
        if constexpr (kRecord) {
            recorder_->path_vertex(c, record);
            if (reason != StopReason::none) recorder_->stop(reason);
            recorder_->end_ray(color);
        }
        return color;
    };
    // Past the last vertex a scattered ray is traced only for the light it meets.
    if (path.depth > settings.max_depth) return end(StopReason::max_depth);

    // A dispersive surface splits a ray that carries every wavelength, as in the distributed
    // integrator: what refracts takes the sample's wavelength and counts by its colour.
    const WavelengthSplit split =
        split_wavelength(m, ray.wavelength, [&] { return stream.get_1d(kWavelengthDimension); });
    const float wavelength = split.wavelength;
    const Color spectral_weight = split.weight;
    if constexpr (kRecord)
        if (split.drawn) recorder_->wavelength(split.u, wavelength);
    const SnellIndices eta = snell_indices(c, path.media, wavelength);
    const Bsdf bsdf(bsdf_inputs(c, eta));
    if (bsdf.has_smooth_part())
        color += next_event_.estimate(c, bsdf, ray.time, stream, stats, /*weigh=*/true,
                                      kRecord ? &record : nullptr);

    const float u_lobe = stream.next_1d();
    const Point2 u = stream.next_2d();
    const std::optional<BsdfSample> s = bsdf.sample(u_lobe, u);
    if (!s) return end(StopReason::none);
    if constexpr (kRecord) {
        constexpr const char* kLobes[] = {"diffuse", "highlight", "reflect", "transmit"};
        record.scattered = true;
        record.lobe = kLobes[int(s->lobe)];
        record.wi = s->wi;
        record.scatter_f = s->f;
        record.scatter_pdf = s->pdf;
        record.delta = s->delta;
        record.weight = s->weight;
    }
    Color factor = s->weight;
    if (s->transmitted) factor *= spectral_weight;
    // Russian roulette: a path whose throughput has fallen below 1 survives with that
    // probability, and what it brings back counts that much more.
    PathState next;
    next.depth = path.depth + 1;
    next.throughput = path.throughput * factor;
    if (const float p = survival_probability(next.throughput, path.depth); p < 1) {
        record.survival = p;
        if (stream.next_1d() >= p) return end(StopReason::roulette);
        factor = factor / p;
        next.throughput = next.throughput / p;
    }
    next.after_delta = s->delta;
    next.bsdf_pdf = s->pdf;
    next.from = c.sp.p;
    if (s->delta)
        next.pencil = s->transmitted
                          ? refraction_pencil(c, ray, or_null(path.pencil), eta.n1 / eta.n2, s->wi)
                          : mirror_pencil(c, ray, or_null(path.pencil));
    Ray scattered = world_.spawn_ray(c.sp.p, c.ng, s->wi, c.sp.error, ray.time);
    scattered.wavelength = s->transmitted ? wavelength : ray.wavelength;
    if (s->transmitted) {
        const float ior = ior_at(m, wavelength);
        next.media = c.entering ? path.media.entered(c.primitive, &m, ior)
                                : path.media.left(c.primitive, &m);
    } else {
        next.media = path.media;
    }
    const RayKind kind = kind_of(s->lobe);
    stats.count(kind);
    if constexpr (kRecord) {
        recorder_->path_vertex(c, record);
        recorder_->branch(kind, factor, s->delta ? std::nullopt : std::optional(u));
    }
    color =
        through(fade, color + factor * radiance<kRecord>(scattered, world_.nearest_hit(scattered),
                                                         next, stream, stats));
    if constexpr (kRecord) recorder_->end_ray(color);
    return color;
}

}  // namespace glint
