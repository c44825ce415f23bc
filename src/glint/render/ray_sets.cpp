// Generating the benchmark ray sets: eye rays, then rays from the surface points they find.
#include "glint/render/ray_sets.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <variant>

#include "glint/math/constants.h"
#include "glint/sampling/random.h"

namespace glint {

namespace {

// Where a primary ray hit: the start of one incoherent and one shadow ray.
struct SurfaceStart {
    Point3 p;
    Normal3 normal;  // geometric, as surface_at gives it
    Normal3 facing;  // the normal turned to the side the eye ray came from
    float error = 0;
};

// The image scaled, aspect kept, to about `count` pixels.
void scaled_image(const RenderSettings& s, std::size_t count, int& width, int& height) {
    const double scale = std::sqrt(double(count) / (double(s.width) * s.height));
    width = std::max(1, int(std::lround(s.width * scale)));
    height = std::max(1, int(std::lround(s.height * scale)));
}

// Uniform on the hemisphere around the unit normal n: cos(theta) is uniform in [0, 1).
Vector3 uniform_hemisphere(Normal3 n, float u1, float u2) {
    Vector3 s, t;
    orthonormal_basis(to_vector(n), s, t);
    const float r = std::sqrt(std::max(0.0f, 1 - u1 * u1));
    const float phi = 2 * kPi * u2;
    return normalize(s * (r * std::cos(phi)) + t * (r * std::sin(phi)) + to_vector(n) * u1);
}

// The shadow rays' target: the first light, or a point above the bounded geometry.
struct LightTarget {
    std::optional<Point3> position;  // nothing for a directional light
    Vector3 to_light;                // for a directional light
};

LightTarget light_target(const World& world) {
    if (!world.lights().empty()) {
        const Light& light = world.lights().front();
        if (const auto* point = std::get_if<PointLight>(&light)) return {point->position, {}};
        return {std::nullopt, -std::get<DirectionalLight>(light).direction};
    }
    Bounds3 bounds;
    for (const Primitive& p : world.primitives()) {
        const Bounds3 b = glint::bounds(p.shape);
        if (b.is_finite()) bounds = merge(bounds, b);
    }
    if (bounds.is_empty()) return {world.camera().eye() + Vector3{0, 1, 0}, {}};
    const Point3 c = bounds.center();
    return {Point3{c.x, bounds.max.y + std::max(length(bounds.diagonal()), 1.0f), c.z}, {}};
}

}  // namespace

RaySets make_ray_sets(const World& world, std::size_t count, std::uint64_t seed) {
    count = std::clamp<std::size_t>(count, 1, kMaxRaysPerSet);
    RaySets out;
    scaled_image(world.settings(), count, out.width, out.height);
    const RenderSettings& s = world.settings();

    RaySet primary{"primary", RayQuery::closest_hit, kVisibleToCameraRays, {}, {}};
    const std::size_t n = std::size_t(out.width) * std::size_t(out.height);
    primary.rays.reserve(n);
    const float sx = float(s.width) / float(out.width), sy = float(s.height) / float(out.height);
    for (int y = 0; y < out.height; ++y)
        for (int x = 0; x < out.width; ++x)
            primary.rays.push_back(
                world.camera().generate_ray({(float(x) + 0.5f) * sx, (float(y) + 0.5f) * sy}));

    // The surface points, in parallel but stored by ray index, so the order is scanline order.
    std::vector<std::optional<SurfaceStart>> found(n);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n), [&](const auto& range) {
        for (std::size_t i = range.begin(); i != range.end(); ++i) {
            const Ray& ray = primary.rays[i];
            const auto hit = world.intersect(ray, {}, kVisibleToCameraRays);
            if (!hit) continue;
            const SurfacePoint sp = world.surface_at(ray, *hit, Uv::skip);
            found[i] =
                SurfaceStart{sp.p, sp.normal, face_forward(sp.normal, -ray.direction), sp.error};
        }
    });
    std::vector<SurfaceStart> starts;
    for (const auto& f : found)
        if (f) starts.push_back(*f);
    found = {};
    out.surface_points = starts.size();

    RaySet incoherent{"incoherent", RayQuery::closest_hit, kVisibleToCameraRays, {}, {}};
    RaySet shadow{"shadow", RayQuery::occluded, kVisibleToShadowRays, {}, {}};
    if (!starts.empty()) {
        incoherent.rays.resize(n);
        shadow.rays.resize(n);
        shadow.ranges.resize(n);
        const LightTarget light = light_target(world);
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n), [&](const auto& range) {
            for (std::size_t i = range.begin(); i != range.end(); ++i) {
                const SurfaceStart& at = starts[i % starts.size()];
                const Vector3 d = uniform_hemisphere(at.facing, random_float(i, 0, 0, seed),
                                                     random_float(i, 0, 1, seed));
                incoherent.rays[i] = world.spawn_ray(at.p, at.normal, d, at.error);

                Vector3 to_light = light.to_light;
                float distance_to_light = kInfinity;
                if (light.position) {
                    to_light = *light.position - at.p;
                    distance_to_light = length(to_light);
                    // A point on the light itself: any direction, an empty segment.
                    to_light =
                        distance_to_light > 0 ? to_light / distance_to_light : to_vector(at.facing);
                }
                const Ray feeler = world.spawn_ray(at.p, at.normal, to_light, at.error);
                // As the Whitted integrator's feelers: stop just short of the light.
                const float remaining = distance_to_light - distance(at.p, feeler.origin);
                shadow.rays[i] = feeler;
                shadow.ranges[i] = {0, std::max(remaining, 0.0f)};
            }
        });
    }
    out.sets.push_back(std::move(primary));
    out.sets.push_back(std::move(incoherent));
    out.sets.push_back(std::move(shadow));
    return out;
}

RaySet in_packet_order(const RaySet& set, int width, int height) {
    if (set.name != "primary") return set;
    RaySet tiled = set;
    tiled.rays.clear();
    constexpr int kTileWidth = 4, kTileHeight = kRayPacketSize / kTileWidth;
    for (int y0 = 0; y0 < height; y0 += kTileHeight)
        for (int x0 = 0; x0 < width; x0 += kTileWidth)
            for (int y = y0; y < std::min(y0 + kTileHeight, height); ++y)
                for (int x = x0; x < std::min(x0 + kTileWidth, width); ++x)
                    tiled.rays.push_back(
                        set.rays[std::size_t(y) * std::size_t(width) + std::size_t(x)]);
    return tiled;
}

}  // namespace glint
