// One feeler, or with transparent shadows a chain of them from surface to surface.
#include "glint/render/integrators/shadow_feelers.h"

#include <cmath>

#include "glint/render/integrators/media_marching.h"
#include "glint/render/integrators/surface_context.h"

namespace glint {

Color ShadowFeelers::transmittance(std::size_t light, const SurfacePoint& sp, Normal3 n,
                                   Vector3 to_light, float light_distance, float time,
                                   RayStats& stats, bool through_transparent) {
    constexpr Color kLit{1, 1, 1};
    if (light != kNoLight && !casts_shadows(world_.lights()[light])) return kLit;
    if (light != kNoLight)
        if (const ShadowMap* map = world_.shadow_map(light)) {
            Lookup& last = last_lookup_[light];
            if (last.visibility >= 0 && last.p.x == sp.p.x && last.p.y == sp.p.y &&
                last.p.z == sp.p.z)
                return Color::gray(last.visibility);
            if (const std::optional<float> lit = map->visibility(sp.p, n)) {
                ++stats.shadow_map_lookups;
                last = {sp.p, *lit};
                return Color::gray(*lit);
            }
        }
    Ray feeler = world_.spawn_ray(sp.p, n, to_light, sp.error, time);
    // The offset origin is slightly nearer to or farther from the light; stop just short of it.
    float remaining = light_distance - distance(sp.p, feeler.origin);
    if (light == kNoLight && std::isfinite(light_distance)) {
        // A point drawn on an emitting object lies on a surface that casts shadows. Aim the
        // feeler from its offset origin at that very point, or near the object's outline it
        // would pierce the surface early; and stop short of the point by the offset a ray
        // leaving it would take, so that the light does not shadow itself.
        const Point3 target = sp.p + to_light * light_distance;
        const Vector3 aim = target - feeler.origin;
        remaining = length(aim);
        feeler.direction = aim / remaining;
        remaining -= world_.ray_epsilon(target);
    }
    if (!transparent_ && !through_transparent) {
        stats.count(RayKind::shadow);
        bool blocked = false;
        if (light == kNoLight)
            blocked = world_.occluded(feeler, {0, remaining}, kVisibleToShadowRays);
        else
            blocked = world_.occluded_towards(light, feeler, {0, remaining}, last_occluder_[light]);
        return blocked ? Color{} : kLit;
    }
    Color factor = kLit;
    for (int crossing = 0; crossing < kMaxShadowCrossings; ++crossing) {
        stats.count(RayKind::shadow);
        const auto hit = world_.intersect(feeler, {0, remaining}, kVisibleToShadowRays);
        if (!hit) return factor;
        const Material& m = world_.material_at(*hit);
        if (m.transmit == 0) return {};
        const bool tints = m.tint > 0;
        const SurfacePoint crossed =
            world_.surface_at(feeler, *hit, tints ? uv_needed(m.color) : Uv::skip);
        factor *= m.transmit;
        if (tints) factor *= tint_filter(m.tint, evaluate(m.color, crossed));
        // Leaving an object by its back, the feeler has crossed its inside since the surface
        // before (an approximation where objects nest or overlap).
        if ((m.fade.fades() || !m.media.empty()) && dot(crossed.normal, feeler.direction) > 0) {
            factor *= fade_over(m.fade, hit->shape_hit.t);
            if (!m.media.empty()) factor *= media_transmittance(m.media, feeler, hit->shape_hit.t);
        }
        if (is_black(factor)) return {};
        // Continue from just beyond the surface crossed.
        const Ray next =
            world_.spawn_ray(crossed.p, crossed.normal, feeler.direction, crossed.error, time);
        remaining -= distance(feeler.origin, next.origin);
        feeler = next;
    }
    return {};
}

}  // namespace glint
