// Cone tracing: gathering what a cone covers, blending it front to back, and the cones a surface
// sends on to the lights, in its mirror direction and through it.
#include "glint/render/integrators/cone_tracer.h"

#include <algorithm>
#include <cmath>

#include "glint/math/constants.h"
#include "glint/render/integrators/local_lighting.h"
#include "glint/render/integrators/ray_fog.h"
#include "glint/render/integrators/surface_context.h"
#include "glint/shading/roughness.h"

namespace glint {

namespace {

std::optional<ConeCoverage> coverage_of(const RayCone& cone, const Shape& shape) {
    if (const auto* s = std::get_if<Sphere>(&shape)) return cone_coverage(cone, *s);
    if (const auto* p = std::get_if<Plane>(&shape)) return cone_coverage(cone, *p);
    if (const auto* p = std::get_if<Polygon>(&shape)) return cone_coverage(cone, p->vertices);
    if (const auto* t = std::get_if<Triangle>(&shape)) return cone_coverage(cone, t->vertices);
    if (const auto* d = std::get_if<Disk>(&shape)) return cone_coverage(cone, *d);
    return std::nullopt;
}

// Whether a bounded shape's bounding sphere lies wholly outside the cone, or outside the part of
// it between start and end along the axis: no point of it is nearer the axis than the cone's
// widest cross-section across the sphere.
bool outside(const RayCone& cone, const Bounds3& b, float start, float end) {
    if (!is_finite(b.min) || !is_finite(b.max)) return false;  // planes: no bounds
    const Point3 c = b.min + (b.max - b.min) * 0.5f;
    const float r = length(b.max - b.min) * 0.5f;
    const Vector3 v = c - cone.apex;
    const float z = dot(v, cone.axis);
    if (z + r < start || z - r > end) return true;
    const float rho = length(v - cone.axis * z);
    return rho - r > cone.spread * std::max(z + r, 0.0f);
}

// The tangent of the half-angle a rough surface's lobe spreads over: where the Phong lobe
// cos^n falls to half its peak.
float lobe_spread(float roughness) {
    if (roughness < kMirrorRoughness) return 0;
    const float n = phong_exponent_of_roughness(roughness);
    return std::tan(std::min(std::acos(std::pow(0.5f, 1 / n)), 1.4f));
}

// The tangent of the half-angle of the cone from p that an area light fills, as a disk of
// the area it shows p.
float light_spread(const AreaLight& light, Vector3 to_light, float distance) {
    const float spread = std::visit(
        [&](const auto& shape) -> float {
            using S = std::decay_t<decltype(shape)>;
            if constexpr (std::is_same_v<S, Sphere>)
                return std::tan(std::asin(std::min(shape.radius / distance, 0.999f)));
            else
                return std::sqrt(shape.area() * std::abs(dot(shape.normal, to_light)) / kPi) /
                       distance;
        },
        light.shape);
    return std::max(spread, 1e-6f);
}

}  // namespace

Color ConeIntegrator::trace_eye_ray(const Ray& ray, const RayDifferential* pencil, SampleStream&,
                                    RayStats& stats) {
    stats.count(RayKind::primary);
    // A cone of the same cross-section as the pixel's footprint.
    float spread = pencil ? std::sqrt(length(cross(pencil->dddx, pencil->dddy)) / kPi) : 1e-4f;
    if (!(spread > 1e-7f)) spread = 1e-7f;  // NaN too
    return trace({ray.origin, ray.direction, spread, ray.time}, ray, kNone, 1, 1, stats,
                 world_.eye_media());
}

void ConeIntegrator::gather(const RayCone& cone, const Ray& axis, std::uint32_t self, float end,
                            std::uint32_t mask, std::vector<ConeHit>& hits) const {
    hits.clear();
    const float start = std::max(dot(axis.origin - cone.apex, cone.axis), 0.0f);
    const auto primitives = world_.primitives();
    for (std::uint32_t i = 0; i < primitives.size(); ++i) {
        const Primitive& p = primitives[i];
        if (!(p.visibility & mask)) continue;
        if (i != self && has_cone_test(p.shape)) {
            if (outside(cone, bounds(p.shape), start, end)) continue;
            const auto c = coverage_of(cone, p.shape);
            if (c && c->depth >= start * (1 - 1e-4f) && c->depth <= end)
                hits.push_back({*c, i, {}});
        } else if (const auto h = intersect(p.shape, axis, {0, end - start})) {
            hits.push_back({ConeCoverage{1, start + h->t, cone.axis}, i, *h});
        }
    }
    std::sort(hits.begin(), hits.end(), [](const ConeHit& a, const ConeHit& b) {
        return a.coverage.depth < b.coverage.depth;
    });
}

Color ConeIntegrator::trace(const RayCone& cone, const Ray& axis, std::uint32_t self, int depth,
                            float weight, RayStats& stats, const MediumStack& media) {
    // Deeper than the scene's depth only through a caller's own depth: a list of its own.
    std::vector<ConeHit> own;
    std::vector<ConeHit>& hits =
        std::size_t(depth) < hits_by_depth_.size() ? hits_by_depth_[std::size_t(depth)] : own;
    gather(cone, axis, self, kInfinity, kVisibleToCameraRays, hits);
    if (depth == 1 && !hits.empty()) ++stats.primary_hits;
    // Front to back, each shape covers its fraction of what the ones before it left uncovered.
    float uncovered = 1;
    Color color;
    for (const ConeHit& hit : hits) {
        if (uncovered < 1e-3f) break;
        const float share = uncovered * hit.coverage.fraction;
        // The point to shade: where the shape's own direction nearest the axis meets it.
        Ray ray = axis;
        std::optional<ShapeHit> found = hit.axis_hit;
        if (!found) {
            ray = {cone.apex, hit.coverage.toward, cone.time, axis.wavelength};
            const float along = std::max(dot(hit.coverage.toward, cone.axis), 1e-6f);
            const float start = std::max(dot(axis.origin - cone.apex, cone.axis), 0.0f);
            found = intersect(world_.primitives()[hit.primitive].shape, ray,
                              {start / along * (1 - 1e-4f), kInfinity});
        }
        if (!found) continue;  // the outline's estimate missed it by a hair: nothing to shade
        // Inside an object that fades, what the cone brings back fades on its way.
        color += share * through(interior_fade(media, found->t),
                                 shade(cone, ray, Hit{*found, hit.primitive}, depth, weight * share,
                                       stats, media));
        uncovered -= share;
    }
    if (uncovered > 0)
        color +=
            uncovered * through(interior_fade(media, kInfinity), world_.sky().radiance(cone.axis));
    return color;
}

Color ConeIntegrator::shade(const RayCone& cone, const Ray& ray, const Hit& hit, int depth,
                            float weight, RayStats& stats, const MediumStack& media) {
    const RenderSettings& settings = world_.settings();
    // The cone as a pencil along the ray (as wide as the cone where the ray starts, spreading as
    // the cone does): image textures filter over its footprint, and its change at the surface
    // is the spread the leaving cones take.
    Vector3 s, t;
    orthonormal_basis(ray.direction, s, t);
    const float start_width = cone.spread * dot(ray.origin - cone.apex, ray.direction);
    const RayDifferential pencil{s * start_width, t * start_width, s * cone.spread,
                                 t * cone.spread};
    const SurfaceContext c = surface_context(world_, ray, hit, &pencil);
    const Material& m = *c.material;
    Color color = c.emission + ambient_term(m, c.ambient_color, world_.ambient());
    // The cone's radius where it meets the surface, and the footprint's as the lights see it:
    // the ellipse it cuts from the surface, foreshortened again towards the light.
    const float distance = dot(c.sp.p - cone.apex, ray.direction);
    const float width = cone.spread * distance;
    const float to_eye = std::max(std::abs(dot(c.n, c.to_viewer)), 0.05f);
    const auto lights = world_.lights();
    for (std::size_t i = 0; i < lights.size(); ++i) {
        const LightSample ls = sample_light(lights[i], c.sp.p);
        if (dot(c.n, ls.to_light) <= 0 || ls.intensity.r + ls.intensity.g + ls.intensity.b <= 0)
            continue;
        float visible;
        if (const auto* area = std::get_if<AreaLight>(&lights[i])) {
            // A soft shadow: the cone from the point that the light fills.
            visible = light_visible(c, hit.primitive, ls.to_light, ls.distance,
                                    light_spread(*area, ls.to_light, ls.distance), ray.time, stats);
        } else {
            // A hard shadow, anti-aliased: the cone from the light through the footprint.
            const float seen = width * std::sqrt(dot(c.n, ls.to_light) / to_eye);
            visible =
                footprint_lit(c, hit.primitive, ls.to_light, ls.distance, seen, ray.time, stats);
        }
        if (visible > 0)
            color += visible * light_term(m, c.color, c.n, ls.to_light, c.to_viewer, ls.intensity);
    }
    if (depth >= settings.max_depth) return color;

    const PencilAtSurface& at = *c.pencil;
    const float side = c.entering ? 1.0f : -1.0f;
    // A cone leaving the surface in direction d: the spread the surface's bending gives the
    // pencil, widened by the lobe; its sides meet behind the surface, where the cone is as wide
    // at the surface as the incoming one.
    auto leaving = [&](Vector3 d, const std::optional<RayDifferential>& bent, float roughness) {
        float spread = cone.spread;
        if (bent) spread = std::sqrt(length(cross(bent->dddx, bent->dddy)));
        spread += lobe_spread(roughness);
        if (!(spread > 1e-7f)) spread = 1e-7f;  // NaN too
        return RayCone{c.sp.p - d * (width / spread), d, spread, cone.time};
    };
    const Branches b = branches_at(c, ray.direction, media, ray.wavelength);
    Color branches;
    if (b.kr > 0 && weight * b.kr >= settings.min_weight) {
        stats.count(RayKind::reflected);
        const Vector3 d = normalize(reflect(ray.direction, c.n));
        std::optional<RayDifferential> bent;
        if (at.bends_known) bent = reflected_pencil(ray, pencil, at, c.n, side);
        branches += b.kr * b.reflect_filter *
                    trace(leaving(d, bent, c.roughness), spawn_from(world_, c, ray, d),
                          hit.primitive, depth + 1, weight * b.kr, stats, media);
    }
    if (b.kt > 0 && weight * b.kt >= settings.min_weight) {
        stats.count(RayKind::refracted);
        std::optional<RayDifferential> bent;
        if (at.bends_known) bent = refracted_pencil(ray, pencil, at, c.n, side, b.eta, b.refracted);
        branches += b.kt * b.filter *
                    trace(leaving(b.refracted, bent, c.transmit_roughness),
                          spawn_from(world_, c, ray, b.refracted), hit.primitive, depth + 1,
                          weight * b.kt, stats, media_beyond(c, b, media));
    }
    return color + branches;
}

float ConeIntegrator::light_visible(const SurfaceContext& c, std::uint32_t self, Vector3 to_light,
                                    float distance, float spread, float time, RayStats& stats) {
    stats.count(RayKind::shadow);
    const Ray feeler = world_.spawn_ray(c.sp.p, c.ng, to_light, c.sp.error, time);
    return uncovered_share({feeler.origin, to_light, spread, time}, feeler, self, distance);
}

float ConeIntegrator::footprint_lit(const SurfaceContext& c, std::uint32_t self, Vector3 to_light,
                                    float distance, float width, float time, RayStats& stats) {
    stats.count(RayKind::shadow);
    // From the light (or, for a directional one, from far along its direction) to the point,
    // as wide as the footprint there; what lies between covers part of it.
    const float reach = std::isfinite(distance)
                            ? distance
                            : 4 * world_.scene_radius() + length(c.sp.p - world_.scene_center());
    const Point3 light = c.sp.p + to_light * reach;
    const Ray feeler = world_.spawn_ray(c.sp.p, c.ng, to_light, c.sp.error, time);
    const float end = reach - length(feeler.origin - c.sp.p);
    const RayCone cone{light, -to_light, std::max(width / reach, 1e-9f), time};
    return uncovered_share(cone, {light, -to_light, time}, self, end);
}

float ConeIntegrator::uncovered_share(const RayCone& cone, const Ray& axis, std::uint32_t self,
                                      float end) {
    gather(cone, axis, self, end, kVisibleToShadowRays, shadow_hits_);
    float uncovered = 1;
    for (const ConeHit& hit : shadow_hits_) uncovered *= 1 - hit.coverage.fraction;
    return uncovered;
}

}  // namespace glint
