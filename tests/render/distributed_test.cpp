// The distributed integrator against values computed another way: the penumbra of a disk light
// behind an occluding disk by numerical integration over the light, an emitting sphere's light
// by its solid angle, and an area light that shrinks to a point light.
#include "glint/render/integrators/distributed.h"

#include <gtest/gtest.h>

#include <cmath>

#include "glint/math/constants.h"
#include "glint/render/integrators/whitted.h"
#include "reference_values.h"

namespace glint {
namespace {

using testing::penumbra_by_integration;

// A white diffuse floor y = 0 (kd 1, nothing else), camera above, no ambient light.
Scene floor_scene() {
    Scene scene;
    scene.settings.width = scene.settings.height = 8;
    scene.settings.integrator = IntegratorKind::distributed;
    scene.camera.from = {0, 10, -1};
    scene.camera.at = {0, 0, 0};
    Material floor;
    floor.ka = 0, floor.kd = 1, floor.ks = 0;
    scene.materials.push_back(floor);
    scene.objects.push_back({Plane{{0, 0, 0}, {0, 1, 0}}, 0});
    return scene;
}

// The mean colour the integrator gives a ray straight down onto the floor at (x, 0, z), over n
// samples of one pixel (jittered, so the light's points are stratified).
float mean_on_floor(const World& world, float x, float z, int n) {
    const Sampler sampler(SamplerKind::jittered, n, 3);
    DistributedIntegrator integrator(world);
    RayStats stats;
    double sum = 0;
    for (int s = 0; s < n; ++s) {
        SampleStream stream(sampler, 0, std::uint32_t(s));
        sum += integrator.trace({{x, 0.01f, z}, {0, -1, 0}}, 2, 1, stream, stats).r;
    }
    return float(sum / n);
}

TEST(Distributed, PenumbraOfADiskLightMatchesNumericalIntegration) {
    Scene scene = floor_scene();
    scene.lights.push_back(disk_light({0, 4, 0}, {0, -1, 0}, 1));
    Material occluder;
    scene.materials.push_back(occluder);
    scene.objects.push_back({Disk{{0, 2, 0}, {0, 1, 0}, 0.5f, 0}, 1});
    const World world(scene);
    // The occluder lies halfway, so it hides q from p when |p + q| / 2 < 0.5: the whole light at
    // the centre (the umbra), part of it for 0 < |x| < 2 (the penumbra), none beyond.
    for (const float x : {0.0f, 0.5f, 1.0f, 1.5f, 2.5f}) {
        const double expected = penumbra_by_integration(x);
        EXPECT_NEAR(mean_on_floor(world, x, 0, 4096), expected, 0.004) << "x = " << x;
    }
    EXPECT_EQ(penumbra_by_integration(0), 0);       // the umbra
    EXPECT_GT(penumbra_by_integration(1.0f), 0.1);  // a penumbra, not a hard shadow
}

TEST(Distributed, EmittingSphereLightsByTheSolidAngleItFills) {
    // A sphere of radiance Le and radius R whose centre is h above a floor point gives
    // irradiance pi Le (R / h)^2; Phong's kd C (N.L) IL integrates that over pi:
    // Le R^2 / h^2 = 4 * 0.25 / 4 = 0.25.
    Scene scene = floor_scene();
    Material glow;
    glow.ka = glow.kd = 0;
    glow.emission = Color::gray(4);
    scene.materials.push_back(glow);
    scene.objects.push_back({Sphere{{0, 2, 0}, 0.5f}, 1});
    const World world(scene);
    ASSERT_EQ(world.object_lights().size(), 1u);
    EXPECT_NEAR(mean_on_floor(world, 0, 0, 4096), 0.25, 0.004);
}

TEST(Distributed, ObjectThatDoesNotEmitLightOnlyGlows) {
    Scene scene = floor_scene();
    Material glow;
    glow.emission = Color::gray(4);
    scene.materials.push_back(glow);
    scene.objects.push_back({Sphere{{0, 2, 0}, 0.5f}, 1, true, /*emits_light=*/false});
    const World world(scene);
    EXPECT_TRUE(world.object_lights().empty());
    EXPECT_EQ(mean_on_floor(world, 0, 0, 16), 0);
}

TEST(Distributed, TinyAreaLightsLightLikeAPointLight) {
    // A point light at (1, 3, 0) gives N.L = 3 / sqrt(10) at the origin (no attenuation).
    const float expected = 3 / std::sqrt(10.0f);
    for (const AreaLight& light :
         {sphere_light({1, 3, 0}, 1e-3f), disk_light({1, 3, 0}, {0, -1, 0}, 1e-3f),
          *rectangle_light({1, 3, 0}, {1e-3f, 0, 0}, {0, 0, 1e-3f})}) {
        Scene scene = floor_scene();
        scene.lights.push_back(light);
        EXPECT_NEAR(mean_on_floor(World(scene), 0, 0, 16), expected, 1e-3f);
    }
}

TEST(Distributed, ShadowRaysPerLightAreAveraged) {
    // A sphere light half hidden by nothing: every shadow ray reaches it. With 3 shadow rays a
    // sample, the sample counts 3 shadow rays and its value stays the light's.
    Scene scene = floor_scene();
    AreaLight light = sphere_light({0, 3, 0}, 0.5f);
    light.shadow_rays = 3;
    scene.lights.push_back(light);
    const World world(scene);
    const Sampler sampler(SamplerKind::jittered, 1, 0);
    SampleStream stream(sampler, 0, 0);
    RayStats stats;
    const Color c =
        DistributedIntegrator(world).trace({{0, 0.01f, 0}, {0, -1, 0}}, 2, 1, stream, stats);
    EXPECT_EQ(stats[RayKind::shadow], 3u);
    EXPECT_GT(c.r, 0.98f);  // N.L is near 1 over the small cap the sphere fills
}

TEST(Whitted, AreaLightIsAPointLightAtItsCentreAndEmittingObjectsOnlyGlow) {
    Scene scene = floor_scene();
    scene.lights.push_back(*rectangle_light({0, 3, 4}, {2, 0, 0}, {0, 0, 2}));
    Material glow;
    glow.emission = Color::gray(4);
    scene.materials.push_back(glow);
    scene.objects.push_back({Sphere{{0, 2, 0}, 0.1f}, 1, false});
    const World world(scene);
    RayStats stats;
    const Color c = WhittedIntegrator(world).trace({{0, 0.01f, 0}, {0, -1, 0}}, 2, 1, stats);
    EXPECT_NEAR(c.r, 3 / 5.0f, 1e-5f);  // N.L towards (0, 3, 4)
    EXPECT_EQ(stats[RayKind::shadow], 1u);
}

}  // namespace
}  // namespace glint
