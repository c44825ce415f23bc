// The lecture notes' TraceRay: closest hit, the Phong terms with one shadow feeler per light,
// then the reflected and refracted rays, cut by depth and by weight.
#include "glint/render/whitted.h"

#include "glint/render/local_lighting.h"
#include "glint/render/surface_context.h"

namespace glint {

Color WhittedIntegrator::trace_eye_ray(const Ray& ray, RayStats& stats) {
    stats.count(RayKind::primary);
    return trace(ray, 1, 1, stats);
}

Color WhittedIntegrator::trace(const Ray& ray, int depth, float weight, RayStats& stats,
                               const MediumStack& media) {
    const RenderSettings& settings = world_.settings();
    const auto hit = world_.intersect(ray, {0, kInfinity}, kVisibleToCameraRays);
    if (!hit) return settings.background;
    if (depth == 1) ++stats.primary_hits;

    const SurfaceContext c = surface_context(world_, ray, *hit);
    const Material& m = *c.material;
    Color color = m.emission + ambient_term(m, c.color, world_.ambient());
    const auto lights = world_.lights();
    for (std::size_t light = 0; light < lights.size(); ++light)
        color += light_sample_term(feelers_, light, c, sample_light(lights[light], c.sp.p),
                                   ray.time, stats);

    if (depth >= settings.max_depth) return color;
    const Branches b = branches_at(c, ray.direction, media, ray.wavelength);
    if (b.kr > 0 && weight * b.kr >= settings.min_weight) {
        stats.count(RayKind::reflected);
        const Ray r = spawn_from(world_, c, ray, normalize(reflect(ray.direction, c.n)));
        color += b.kr * trace(r, depth + 1, weight * b.kr, stats, media);
    }
    if (b.kt > 0 && weight * b.kt >= settings.min_weight) {
        stats.count(RayKind::refracted);
        const Ray t = spawn_from(world_, c, ray, b.refracted);
        color += b.kt * trace(t, depth + 1, weight * b.kt, stats, media_beyond(c, b, media));
    }
    return color;
}

}  // namespace glint
