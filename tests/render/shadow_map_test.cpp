// Shadow maps (shadows: map) against what is known: the depths they store with worked numbers,
// and their images against the shadow feelers', equal away from the shadows' edges.
#include "glint/render/shadow_map.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

#include "glint/render/render.h"

namespace glint {
namespace {

// A floor, a ball on it and a box, seen from above at a slant, lit by `light`.
Scene ball_and_box(const Light& light, IntegratorKind integrator) {
    Scene scene;
    scene.settings.width = 64;
    scene.settings.height = 48;
    scene.settings.integrator = integrator;
    scene.settings.samples_per_pixel = integrator == IntegratorKind::whitted ? 1 : 64;
    scene.settings.filter = FilterSpec{FilterKind::box, 0.5f};
    scene.camera.from = {0, 6, -7};
    scene.camera.at = {0, 0, 0};
    scene.camera.fov = 50;
    Material matte;
    matte.ka = 0;
    matte.kd = 0.8f;
    matte.ks = 0;
    scene.materials = {matte};
    scene.objects.push_back({Plane{{0, 0, 0}, {0, 1, 0}}, 0});
    scene.objects.push_back({Sphere{{-1, 1, 0}, 1}, 0});
    scene.objects.push_back({Box{{1, 0, -1}, {2.5f, 1.5f, 0.5f}}, 0});
    scene.lights = {light};
    return scene;
}

PointLight point_light() {
    PointLight light;
    light.position = {-3, 7, -4};
    return light;
}

Image rendered(Scene scene, ShadowMethod shadows, RayStats* rays = nullptr) {
    scene.settings.shadows = shadows;
    const RenderResult r = render(World(std::move(scene)), {});
    if (rays) *rays = r.rays;
    return r.image;
}

float grey(const Color& c) { return (c.r + c.g + c.b) / 3; }

// Where the two images differ by more than `tolerance`, the feelers' image must have an edge
// within `reach` pixels (a neighbour that differs from the pixel by more than 0.05); and those
// pixels must be few. The largest difference away from edges.
void expect_equal_away_from_edges(const Image& feelers, const Image& map, float tolerance,
                                  int reach) {
    int differing = 0, off_edges = 0;
    for (int y = 0; y < feelers.height; ++y)
        for (int x = 0; x < feelers.width; ++x) {
            const float a = grey(feelers.at(x, y)), b = grey(map.at(x, y));
            if (std::abs(a - b) <= tolerance) continue;
            ++differing;
            bool edge = false;
            for (int dy = -reach; dy <= reach && !edge; ++dy)
                for (int dx = -reach; dx <= reach && !edge; ++dx) {
                    const int nx = x + dx, ny = y + dy;
                    if (nx < 0 || ny < 0 || nx >= feelers.width || ny >= feelers.height) continue;
                    edge = std::abs(grey(feelers.at(nx, ny)) - a) > 0.05f;
                }
            if (!edge) {
                ++off_edges;
                ADD_FAILURE() << "pixel (" << x << ", " << y << "): feelers " << a << ", map " << b
                              << ", no shadow edge within " << reach << " pixels";
            }
        }
    EXPECT_EQ(off_edges, 0);
    EXPECT_LT(differing, feelers.width * feelers.height / 20);
}

// A point light at the origin over a ball of radius 1 whose top is 4 below it, on a floor 5
// below: straight down the map stores 2 (the cube's depths are along its face's axis). Towards
// (2, -1, 0), by the +x face at u = y / x = -1/2, the texel of 64 whose centre is at
// u = 33/64 - 1 = -31/64 meets the floor where x = 5 / (31/64) = 10.32.
TEST(ShadowMap, StoresTheNearestSurfaceAlongTheFacesAxis) {
    PointLight light;
    light.position = {0, 0, 0};
    Scene scene;
    scene.settings.shadows = ShadowMethod::map;
    scene.settings.shadow_map.resolution = 64;
    scene.camera.from = {0, 0, -10};
    scene.materials.resize(1);
    scene.objects.push_back({Plane{{0, -5, 0}, {0, 1, 0}}, 0});
    scene.objects.push_back({Sphere{{0, -3, 0}, 1}, 0});
    scene.lights = {light};
    const World world(scene);
    const ShadowMap* map = world.shadow_map(0);
    ASSERT_NE(map, nullptr);
    EXPECT_NEAR(map->depth_towards({0, -1, 0}), 2, 2e-3);
    EXPECT_NEAR(map->depth_towards({2, -1, 0}), 5 * 64 / 31.0, 1e-3);
    EXPECT_TRUE(std::isinf(map->depth_towards({0, 1, 0})));  // nothing above
    EXPECT_EQ(map->memory_bytes(), 6u * 64 * 64 * sizeof(float));
}

TEST(ShadowMap, APointLightsShadowsAreTheFeelersAwayFromTheirEdges) {
    const Scene scene = ball_and_box(point_light(), IntegratorKind::whitted);
    RayStats rays;
    const Image map = rendered(scene, ShadowMethod::map, &rays);
    expect_equal_away_from_edges(rendered(scene, ShadowMethod::feelers), map, 0.02f, 2);
    // No feelers: every shadow was looked up.
    EXPECT_EQ(rays[RayKind::shadow], 0u);
    EXPECT_GT(rays.shadow_map_lookups, 0u);
}

TEST(ShadowMap, ADirectionalLightsShadowsAreTheFeelersAwayFromTheirEdges) {
    DirectionalLight sun;
    sun.direction = normalize(Vector3{1, -2, 1.5f});
    const Scene scene = ball_and_box(sun, IntegratorKind::whitted);
    expect_equal_away_from_edges(rendered(scene, ShadowMethod::feelers),
                                 rendered(scene, ShadowMethod::map), 0.02f, 2);
}

TEST(ShadowMap, ASpotLightsShadowsAreTheFeelersAwayFromTheirEdges) {
    SpotLight spot;
    spot.position = {-3, 7, -4};
    spot.direction = normalize(Vector3{3, -7, 4});
    spot.cos_cone = std::cos(0.7f);
    spot.cos_falloff = std::cos(0.6f);
    const Scene scene = ball_and_box(spot, IntegratorKind::whitted);
    expect_equal_away_from_edges(rendered(scene, ShadowMethod::feelers),
                                 rendered(scene, ShadowMethod::map), 0.02f, 2);
}

// An area light's penumbrae by percentage-closer soft shadows: an estimate from the blockers'
// mean depth, not the light's visible part, so wider reach and tolerance; in the umbrae and the
// fully lit parts the same.
TEST(ShadowMap, AnAreaLightsSoftShadowsFollowTheFeelersPenumbrae) {
    AreaLight disk = disk_light({-3, 7, -4}, Normal3(normalize(Vector3{3, -7, 4})), 0.8f);
    const Scene scene = ball_and_box(disk, IntegratorKind::distributed);
    const Image feelers = rendered(scene, ShadowMethod::feelers);
    const Image map = rendered(scene, ShadowMethod::map);
    expect_equal_away_from_edges(feelers, map, 0.04f, 5);
    double difference = 0;
    for (std::size_t i = 0; i < feelers.pixels.size(); ++i)
        difference += std::abs(grey(feelers.pixels[i]) - grey(map.pixels[i]));
    EXPECT_LT(difference / double(feelers.pixels.size()), 0.01);
}

}  // namespace
}  // namespace glint
