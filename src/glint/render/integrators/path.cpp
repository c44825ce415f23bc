// Path tracing: a recursion along one path (each ray's radiance is its vertex's emitted and
// direct light plus the scattered ray's, times the BSDF's weight), so that `glint explain`
// records it as the ray tree it is, a tree of one branch.
#include "glint/render/integrators/path.h"

#include <algorithm>
#include <vector>

#include "glint/render/integrators/surface_context.h"
#include "glint/shading/cie_1931.h"
#include "glint/shading/emission.h"
#include "glint/shading/object_light.h"
#include "glint/shading/spectrum.h"

namespace glint {

namespace {

// Paths that have scattered this often may end by Russian roulette.
constexpr int kRouletteDepth = 3;
// The least probability a path survives the roulette with.
constexpr float kLeastSurvival = 0.05f;

BsdfInputs bsdf_inputs(const SurfaceContext& c, SnellIndices eta) {
    const Material& m = *c.material;
    BsdfInputs in;
    in.wo = c.to_viewer;
    in.n = c.n;
    in.ng = c.ng;
    in.kd = m.kd;
    in.color = c.color;
    in.ks = m.ks;
    in.shininess = m.shininess;
    in.reflect = c.reflect;
    in.roughness = c.roughness;
    in.transmit = m.transmit;
    in.transmit_roughness = c.transmit_roughness;
    in.n1 = eta.n1;
    in.n2 = eta.n2;
    in.fresnel = m.fresnel;
    return in;
}

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

float mean(Color c) { return (c.r + c.g + c.b) / 3; }

}  // namespace

PathIntegrator::Shared PathIntegrator::prepare(const World& world) {
    std::vector<float> power;
    const float radius = world.scene_radius();
    for (const Light& light : world.lights()) power.push_back(mean(light_power(light, radius)));
    for (const ObjectLight& light : world.object_lights())
        power.push_back(mean(object_light_power(light)));
    float total = 0;
    for (float& p : power) {
        if (!std::isfinite(p) || p < 0) p = 0;
        total += p;
    }
    if (!(total > 0)) return {};
    return {std::make_shared<const DiscreteDistribution>(power)};
}

Color PathIntegrator::trace_eye_ray(const Ray& ray, SampleStream& stream, RayStats& stats) {
    stats.count(RayKind::primary);
    PathState path;
    path.media = world_.eye_media();
    if (recorder_) [[unlikely]]
        return radiance<true>(ray, path, stream, stats);
    return radiance<false>(ray, path, stream, stats);
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
    if (index < 0 || !shared_.light_pick) return {1, path.bsdf_pdf, 0};
    const ObjectLight& light = world_.object_lights()[std::size_t(index)];
    const float pick = shared_.light_pick->probability(world_.lights().size() + std::size_t(index));
    const float light_pdf = pick * object_light_pdf(light, path.from, c.sp.p, c.sp.normal);
    return {power_heuristic(path.bsdf_pdf, light_pdf), path.bsdf_pdf, light_pdf};
}

Color PathIntegrator::direct_light(const SurfaceContext& c, const Bsdf& bsdf, float time,
                                   SampleStream& stream, RayStats& stats,
                                   PathVertexRecord* record) {
    if (!shared_.light_pick) return {};
    const float u_pick = stream.next_1d();
    const Point2 u = stream.next_2d();
    const std::size_t index = shared_.light_pick->sample(u_pick);
    const float pick = shared_.light_pick->probability(index);
    const auto lights = world_.lights();
    LightSample ls;
    std::size_t feeler_light = ShadowFeelers::kNoLight;
    float light_pdf = 0;
    if (index < lights.size()) {
        // Point, spot, directional and area lights: no scattered ray ever hits them. An area
        // light's point is drawn over all its shape, as the particles of the light integrator
        // leave it, so that the two agree.
        ls = sample_light_by_area(lights[index], c.sp.p, u);
        feeler_light = index;
    } else {
        const ObjectLightSample s =
            sample_object_light(world_.object_lights()[index - lights.size()], c.sp.p, u);
        ls = s.light;
        light_pdf = s.pdf;
        if (!(s.pdf > 0)) ls.intensity = {};
    }
    const bool sends = !is_black(ls.intensity);
    const Color f = sends ? bsdf.eval(ls.to_light) : Color{};
    const float bsdf_pdf = sends ? bsdf.pdf(ls.to_light) : 0;
    const float mis = light_pdf > 0 ? power_heuristic(pick * light_pdf, bsdf_pdf) : 1;
    const float cosine = std::abs(dot(to_vector(c.n), ls.to_light));
    float shadow = 0;
    Color term;
    if (!is_black(f)) {
        // Light from behind reaches only what transmits: the feeler leaves by that side.
        const Normal3 side = dot(ls.to_light, c.ng) >= 0 ? c.ng : -c.ng;
        shadow =
            feelers_.transmittance(feeler_light, c.sp, side, ls.to_light, ls.distance, time, stats);
        // A light of intensity I_L gives irradiance pi I_L facing it (light.h); an object
        // light's pi I_L is Le over the density of the direction drawn.
        if (shadow > 0) term = f * ls.intensity * (kPi * cosine * shadow * mis / pick);
    }
    if (record) {
        record->light_sampled = true;
        record->light = light_name(index);
        record->pick = pick;
        record->to_light = ls.to_light;
        record->distance = ls.distance;
        record->irradiance = ls.intensity * kPi;
        record->f = f;
        record->cosine = cosine;
        record->light_pdf = light_pdf;
        record->bsdf_pdf = bsdf_pdf;
        record->mis = mis;
        record->shadow = shadow;
        record->term = term;
    }
    return term;
}

std::string PathIntegrator::light_name(std::size_t index) const {
    const std::size_t lights = world_.lights().size();
    if (index < lights) return "light " + std::to_string(index);
    return "emitting object " + std::to_string(world_.object_lights()[index - lights].primitive);
}

template <bool kRecord>
Color PathIntegrator::radiance(const Ray& ray, PathState path, SampleStream& stream,
                               RayStats& stats) {
    const RenderSettings& settings = world_.settings();
    if constexpr (kRecord) recorder_->begin_ray(ray, path.depth, 1);
    const auto hit = world_.intersect(ray, {0, kInfinity}, kVisibleToCameraRays);
    if (!hit) {
        // The background is a sky that lights the scene, found by scattered rays alone.
        if constexpr (kRecord) {
            recorder_->missed(settings.background);
            recorder_->end_ray(settings.background);
        }
        return settings.background;
    }
    if (path.depth == 1) ++stats.primary_hits;
    const SurfaceContext c = surface_context(world_, ray, *hit);
    if constexpr (kRecord) recorder_->hit(c, *hit);
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
    float wavelength = ray.wavelength;
    Color spectral_weight{1, 1, 1};
    if (m.dispersion.model != DispersionModel::none && m.transmit > 0 && wavelength == 0) {
        const float u = stream.get_1d(kWavelengthDimension);
        wavelength = sample_visible_wavelength(u);
        spectral_weight = wavelength_to_rgb_weight(wavelength) / visible_wavelength_pdf(wavelength);
        if constexpr (kRecord) recorder_->wavelength(u, wavelength);
    }
    const Bsdf bsdf(bsdf_inputs(c, snell_indices(c, path.media, wavelength)));
    if (bsdf.has_smooth_part())
        color += direct_light(c, bsdf, ray.time, stream, stats, kRecord ? &record : nullptr);

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
    if (path.depth >= kRouletteDepth) {
        const float survival = std::min(1.0f, max_channel(next.throughput));
        if (survival < 1) {
            const float p = std::max(kLeastSurvival, survival);
            record.survival = p;
            if (stream.next_1d() >= p) return end(StopReason::roulette);
            factor = factor / p;
            next.throughput = next.throughput / p;
        }
    }
    next.after_delta = s->delta;
    next.bsdf_pdf = s->pdf;
    next.from = c.sp.p;
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
    color += factor * radiance<kRecord>(scattered, next, stream, stats);
    if constexpr (kRecord) recorder_->end_ray(color);
    return color;
}

}  // namespace glint
