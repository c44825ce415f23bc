// Distributed ray tracing: Whitted's recursion with every light sampled over its area.
#include "glint/render/distributed.h"

#include "glint/render/glossy_lobe.h"
#include "glint/render/local_lighting.h"
#include "glint/render/surface_context.h"
#include "glint/sampling/warp.h"

namespace glint {

namespace {

// A lobe's numbers: a dimension of its own when the surface is rough, none for a mirror.
Point2 lobe_sample(float roughness, SampleStream& stream) {
    return roughness < kMirrorRoughness ? Point2{0, 0} : stream.next_2d();
}

}  // namespace

Color DistributedIntegrator::trace_eye_ray(const Ray& ray, SampleStream& stream, RayStats& stats) {
    stats.count(RayKind::primary);
    return trace(ray, 1, 1, stream, stats);
}

Color DistributedIntegrator::trace(const Ray& ray, int depth, float weight, SampleStream& stream,
                                   RayStats& stats, const MediumStack& media) {
    const RenderSettings& settings = world_.settings();
    const auto hit = world_.intersect(ray, {0, kInfinity}, kVisibleToCameraRays);
    if (!hit) return settings.background;
    if (depth == 1) ++stats.primary_hits;

    const SurfaceContext c = surface_context(world_, ray, *hit);
    const Material& m = *c.material;
    Color color = m.emission + ambient_term(m, c.color, world_.ambient());
    color += direct_light(c, ray, stream, stats);

    if (depth >= settings.max_depth) return color;
    // A dispersive surface splits a ray that carries every wavelength: the refracted ray takes
    // the sample's wavelength, and what it brings back counts by that wavelength's colour.
    Ray parent = ray;
    Color spectral_weight{1, 1, 1};
    if (m.dispersion.model != DispersionModel::none && m.transmit > 0 && ray.wavelength == 0) {
        parent.wavelength = sample_visible_wavelength(stream.get_1d(kWavelengthDimension));
        spectral_weight =
            wavelength_to_rgb_weight(parent.wavelength) / visible_wavelength_pdf(parent.wavelength);
    }
    const Branches b = branches_at(c, ray.direction, media, parent.wavelength);
    if (b.kr > 0 && weight * b.kr >= settings.min_weight) {
        const Vector3 mirror = normalize(reflect(ray.direction, c.n));
        const Vector3 d = spread_over_lobe(mirror, c.roughness, lobe_sample(c.roughness, stream),
                                           to_vector(c.ng), true);
        if (d != kBlockedByTheSurface) {
            stats.count(RayKind::reflected);
            const Ray r = spawn_from(world_, c, ray, d);
            color += b.kr * trace(r, depth + 1, weight * b.kr, stream, stats, media);
        }
    }
    if (b.kt > 0 && weight * b.kt >= settings.min_weight) {
        const Vector3 d =
            spread_over_lobe(b.refracted, c.transmit_roughness,
                             lobe_sample(c.transmit_roughness, stream), to_vector(c.ng), false);
        if (d != kBlockedByTheSurface) {
            stats.count(RayKind::refracted);
            const Ray t = spawn_from(world_, c, parent, d);
            color += b.kt * spectral_weight *
                     trace(t, depth + 1, weight * b.kt, stream, stats,
                           media_beyond(c, b, media, parent.wavelength));
        }
    }
    return color;
}

Color DistributedIntegrator::direct_light(const SurfaceContext& c, const Ray& ray,
                                          SampleStream& stream, RayStats& stats) {
    Color sum;
    const auto lights = world_.lights();
    for (std::size_t light = 0; light < lights.size(); ++light) {
        if (!is_area_light(lights[light])) {
            sum += light_sample_term(feelers_, light, c, sample_light(lights[light], c.sp.p),
                                     ray.time, stats);
            continue;
        }
        // n shadow rays, stratified together with those of the pixel's other samples.
        const int own = std::get<AreaLight>(lights[light]).shadow_rays;
        const auto n = std::uint32_t(own > 0 ? own : world_.settings().shadow_rays);
        const std::uint32_t dimension = stream.next_dimension();
        Color light_sum;
        for (std::uint32_t j = 0; j < n; ++j) {
            const LightSample ls =
                sample_light(lights[light], c.sp.p, stream.get_2d(dimension, j, n));
            light_sum += light_sample_term(feelers_, light, c, ls, ray.time, stats);
        }
        sum += light_sum / float(n);
    }
    const auto n = std::uint32_t(world_.settings().shadow_rays);
    for (const ObjectLight& light : world_.object_lights()) {
        const std::uint32_t dimension = stream.next_dimension();
        Color light_sum;
        for (std::uint32_t j = 0; j < n; ++j) {
            const LightSample ls = sample_light(light, c.sp.p, stream.get_2d(dimension, j, n));
            light_sum +=
                light_sample_term(feelers_, ShadowFeelers::kNoLight, c, ls, ray.time, stats);
        }
        sum += light_sum / float(n);
    }
    return sum;
}

}  // namespace glint
