// The lecture notes' TraceRay: closest hit, the Phong terms with one shadow feeler per light,
// then the reflected and refracted rays, cut by depth and by weight.
#include "glint/render/whitted.h"

#include "glint/shading/optics.h"
#include "glint/shading/phong.h"

namespace glint {

Color WhittedIntegrator::trace_eye_ray(const Ray& ray, RayStats& stats) {
    stats.count(RayKind::primary);
    return trace(ray, 1, 1, stats);
}

Color WhittedIntegrator::trace(const Ray& ray, int depth, float weight, RayStats& stats) {
    const RenderSettings& settings = world_.settings();
    const auto hit = world_.intersect(ray, {0, kInfinity}, kVisibleToCameraRays);
    if (!hit) return settings.background;
    if (depth == 1) ++stats.primary_hits;

    const SurfacePoint sp = world_.surface_at(ray, *hit);
    const Material& m = world_.material_of(hit->primitive);
    const Color surface_color = evaluate(m.color, sp);
    // The ray enters the surface when it meets the front (outward) side. Both normals are
    // turned to face the incoming ray: the geometric one places secondary rays on the right
    // side of the surface, the shading one (smooth for meshes) enters the formulas.
    const bool entering = dot(sp.normal, ray.direction) < 0;
    const Normal3 ng = entering ? sp.normal : -sp.normal;
    const Normal3 n = entering ? sp.shading_normal : -sp.shading_normal;
    const Vector3 to_viewer = -ray.direction;

    Color color = m.emission + ambient_term(m, surface_color, world_.ambient());
    const auto lights = world_.lights();
    for (std::size_t light = 0; light < lights.size(); ++light) {
        const LightSample ls = sample_light(lights[light], sp.p);
        // A light behind the surface adds nothing, so it needs no feeler.
        if (dot(n, ls.to_light) <= 0) continue;
        const float shadow = shadow_factor(light, sp, ng, ls.to_light, ls.distance, stats);
        if (shadow == 0) continue;
        color += shadow * light_term(m, surface_color, n, ls.to_light, to_viewer, ls.intensity);
    }

    if (depth >= settings.max_depth) return color;
    float kr = m.reflect, kt = m.transmit;
    Vector3 refracted;
    if (kt > 0) {
        // Snell's law; on total internal reflection the transmitted energy is reflected.
        const float eta = entering ? 1 / m.ior : m.ior;
        if (const auto t = refract(ray.direction, n, eta)) {
            refracted = normalize(*t);
        } else {
            kr += kt;
            kt = 0;
        }
    }
    if (kr > 0 && weight * kr >= settings.min_weight) {
        stats.count(RayKind::reflected);
        const Ray r = world_.spawn_ray(sp.p, ng, normalize(reflect(ray.direction, n)), sp.error);
        color += kr * trace(r, depth + 1, weight * kr, stats);
    }
    if (kt > 0 && weight * kt >= settings.min_weight) {
        stats.count(RayKind::refracted);
        const Ray t = world_.spawn_ray(sp.p, ng, refracted, sp.error);
        color += kt * trace(t, depth + 1, weight * kt, stats);
    }
    return color;
}

float WhittedIntegrator::shadow_factor(std::size_t light, const SurfacePoint& sp, Normal3 n,
                                       Vector3 to_light, float light_distance, RayStats& stats) {
    Ray feeler = world_.spawn_ray(sp.p, n, to_light, sp.error);
    // The offset origin is slightly nearer to or farther from the light; stop just short of it.
    float remaining = light_distance - distance(sp.p, feeler.origin);
    if (!world_.settings().transparent_shadows) {
        stats.count(RayKind::shadow);
        return world_.occluded_towards(light, feeler, {0, remaining}, last_occluder_[light]) ? 0.0f
                                                                                             : 1.0f;
    }
    float factor = 1;
    for (int crossing = 0; crossing < kMaxShadowCrossings; ++crossing) {
        stats.count(RayKind::shadow);
        const auto hit = world_.intersect(feeler, {0, remaining}, kVisibleToShadowRays);
        if (!hit) return factor;
        factor *= world_.material_of(hit->primitive).transmit;
        if (factor == 0) return 0;
        // Continue from just beyond the surface crossed.
        const SurfacePoint crossed = world_.surface_at(feeler, *hit);
        const Ray next = world_.spawn_ray(crossed.p, crossed.normal, to_light, crossed.error);
        remaining -= distance(feeler.origin, next.origin);
        feeler = next;
    }
    return 0;
}

}  // namespace glint
