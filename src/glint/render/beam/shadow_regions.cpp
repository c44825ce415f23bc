// Each occluder is cut to the slab between the receiving plane and the light, projected onto the
// plane from the light (or along a directional light's direction), and the union of those
// shadows is taken from the receiver.
#include "glint/render/beam/shadow_regions.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <optional>

namespace glint::beam {

namespace {

// Where the light is: a point, or (directional) only a direction towards it.
struct LightPlace {
    Vector3d point;
    std::optional<Vector3d> direction;  // unit, towards the light
};

LightPlace place_of(const Light& light) {
    if (const auto* p = std::get_if<PointLight>(&light)) return {Vector3d(p->position), {}};
    if (const auto* s = std::get_if<SpotLight>(&light)) return {Vector3d(s->position), {}};
    if (const auto* a = std::get_if<AreaLight>(&light)) return {Vector3d(a->center), {}};
    const auto& d = std::get<DirectionalLight>(light);
    return {{}, Vector3d(d.direction) * -1.0};
}

// A polygon's bounding sphere as the light sees it: the cheap test that rules out most pairs
// before any clipping.
struct Bounds {
    Vector3d center;
    double radius = 0;
    Vector3d direction;  // unit, from a point light to the centre
    double distance = 0;
    double cos_spread = 1, sin_spread = 0;  // of the sphere's angular radius from a point light
};

Bounds bounds_of_polygon(const BeamPolygon& p, const LightPlace& light) {
    Bounds b;
    std::size_t n = 0;
    for (const Path& ring : p.region)
        for (const IntPoint& q : ring) b.center = b.center + p.frame.world(q), ++n;
    b.center = b.center * (1 / double(std::max<std::size_t>(n, 1)));
    for (const Path& ring : p.region)
        for (const IntPoint& q : ring) {
            const Vector3d d = p.frame.world(q) - b.center;
            b.radius = std::max(b.radius, std::sqrt(dot(d, d)));
        }
    b.radius *= 1 + 1e-9;
    if (!light.direction) {
        const Vector3d d = b.center - light.point;
        b.distance = std::sqrt(dot(d, d));
        if (b.distance > b.radius) {
            b.direction = d * (1 / b.distance);
            b.sin_spread = b.radius / b.distance;
            b.cos_spread = std::sqrt(1 - b.sin_spread * b.sin_spread);
        } else {
            b.cos_spread = -1;  // round the light: any direction
        }
    }
    return b;
}

// Whether q's sphere can shadow r's: it overlaps the cone (or, for a directional light, the
// cylinder) from the light round r's sphere, on the light's side of r's far end.
bool may_shadow(const Bounds& q, const Bounds& r, const LightPlace& light) {
    if (light.direction) {
        const Vector3d d = q.center - r.center;
        const double along = dot(d, *light.direction);
        if (along < -(q.radius + r.radius)) return false;
        const Vector3d across = d - *light.direction * along;
        const double reach = q.radius + r.radius;
        return dot(across, across) <= reach * reach;
    }
    if (q.distance - q.radius > r.distance + r.radius) return false;
    if (q.cos_spread < 0 || r.cos_spread < 0) return true;
    // The angle between the centres within the sum of the angular radii (each at most 90
    // degrees, so the cosine falls all the way).
    const double cos_sum = q.cos_spread * r.cos_spread - q.sin_spread * r.sin_spread;
    return dot(q.direction, r.direction) >= cos_sum;
}

LightReach reach_of(const LightPlace& light, std::size_t receiver,
                    std::span<const BeamPolygon> polygons, std::span<const Bounds> bounds,
                    double tolerance) {
    const BeamPolygon& r = polygons[receiver];
    // The receiving plane turned to face the light.
    PlaneD plane = r.plane;
    double height;  // of the light above the plane; for a directional light, the cosine
    if (light.direction) {
        height = dot(plane.n, *light.direction);
        if (height < 0) plane = plane.flipped(), height = -height;
    } else {
        height = plane.at(light.point);
        if (height < 0) plane = plane.flipped(), height = -height;
    }
    // A light in the plane grazes it and lights nothing that the shading would not zero. (A
    // directional light within a millionth of the plane would also throw shadows a million
    // times their height, beyond what the integer coordinates hold.)
    if (height <= (light.direction ? 1e-6 : tolerance)) return {};
    const PlaneD above{plane.n, plane.d + tolerance};
    // Below the light, by a margin that keeps projected points finite.
    const std::optional<PlaneD> below =
        light.direction
            ? std::nullopt
            : std::optional<PlaneD>(PlaneD{plane.n * -1.0, -(plane.d + height * 0.9999)});
    const ClipperLib::IntRect box = bounds_of(r.region);
    Paths shadows;
    for (std::size_t i = 0; i < polygons.size(); ++i) {
        const BeamPolygon& q = polygons[i];
        if (i == receiver || !q.casts_shadows) continue;
        if (!may_shadow(bounds[i], bounds[receiver], light)) continue;
        Side s = side_of(q.frame, q.region, above, 0);
        if (s == Side::back || s == Side::in_plane) continue;
        Paths part = s == Side::front ? q.region : clip_to_halfspace(q.frame, q.region, above);
        if (below) part = clip_to_halfspace(q.frame, part, *below);
        if (part.empty()) continue;
        Paths shadow;
        for (const Path& ring : part) {
            Path projected;
            for (const IntPoint& p : ring) {
                const Vector3d x = q.frame.world(p);
                const double h = plane.at(x);
                const Vector3d onto =
                    light.direction ? x - *light.direction * (h / height)
                                    : light.point + (x - light.point) * (height / (height - h));
                projected.push_back(r.frame.local(onto));
            }
            shadow.push_back(std::move(projected));
        }
        if (!overlap(bounds_of(shadow), box)) continue;
        // A projection may turn the occluder over; its rings go back to positive outer rings so
        // that, added up under the non-zero rule, shadows do not cancel each other.
        orient_positive(shadow);
        shadows.insert(shadows.end(), shadow.begin(), shadow.end());
    }
    if (shadows.empty()) return {};
    return {false, difference(r.region, union_of(shadows))};
}

}  // namespace

std::vector<std::vector<LightReach>> light_reach(std::span<const Light> lights,
                                                 std::span<const BeamPolygon> polygons,
                                                 double tolerance) {
    std::vector<std::vector<LightReach>> reach(lights.size());
    for (std::size_t l = 0; l < lights.size(); ++l) {
        const LightPlace place = place_of(lights[l]);
        std::vector<Bounds> bounds;
        bounds.reserve(polygons.size());
        for (const BeamPolygon& p : polygons) bounds.push_back(bounds_of_polygon(p, place));
        reach[l].resize(polygons.size());
        tbb::parallel_for(std::size_t{0}, polygons.size(), [&](std::size_t i) {
            reach[l][i] = reach_of(place, i, polygons, bounds, tolerance);
        });
    }
    return reach;
}

}  // namespace glint::beam
