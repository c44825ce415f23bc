// Participating media: the marching's worked numbers, and media inside objects seen by the
// Whitted and distributed integrators, through hollow objects and in shadows.
#include <gtest/gtest.h>

#include <cmath>

#include "glint/render/integrators/media_marching.h"
#include "glint/render/render.h"
#include "scene_parts.h"

namespace glint {
namespace {

// A world of nothing but a light shining along +z (its direction to the light -z).
World lit_along_z() {
    Scene scene;
    scene.lights.push_back(DirectionalLight{{0, 0, 1}, {1, 1, 1}});
    return World(scene);
}

FogEffect marched(const World& world, const Medium& medium, const Ray& ray, float length) {
    ShadowFeelers feelers(world);
    RayStats stats;
    const std::vector<Medium> media{medium};
    return march_media(world, feelers, media, ray, length, 0.5f, stats);
}

TEST(Media, AGlowingAbsorbingMediumAddsItsEmissionAttenuated) {
    // sigma_t = 0.2 over 2: T = exp(-0.4); the emission 0.5 adds 0.5 (1 - exp(-0.4)) / 0.2.
    Medium m;
    m.absorption = Color::gray(0.2f);
    m.emission = Color::gray(0.5f);
    const FogEffect e = marched(lit_along_z(), m, Ray{{0, 0, 0}, {1, 0, 0}}, 2);
    EXPECT_NEAR(e.transmittance.r, std::exp(-0.4f), 1e-6f);
    EXPECT_NEAR(e.added.g, 0.5f * (1 - std::exp(-0.4f)) / 0.2f, 1e-5f);
}

TEST(Media, AScatteringMediumAddsTheLightItTurnsTowardsTheViewer) {
    // Isotropic, sigma_s = (0.3, 0.1, 0), sigma_a = 0.1: sigma_t = (0.4, 0.2, 0.1) over 3; the
    // light of 1 everywhere gives S = sigma_s, and S (1 - exp(-sigma_t 3)) / sigma_t.
    Medium m;
    m.absorption = Color::gray(0.1f);
    m.scattering = {0.3f, 0.1f, 0};
    const FogEffect e = marched(lit_along_z(), m, Ray{{0, 0, 0}, {1, 0, 0}}, 3);
    EXPECT_NEAR(e.transmittance.r, std::exp(-1.2f), 1e-6f);
    EXPECT_NEAR(e.transmittance.b, std::exp(-0.3f), 1e-6f);
    EXPECT_NEAR(e.added.r, 0.3f * (1 - std::exp(-1.2f)) / 0.4f, 1e-5f);
    EXPECT_NEAR(e.added.g, 0.1f * (1 - std::exp(-0.6f)) / 0.2f, 1e-5f);
    EXPECT_EQ(e.added.b, 0);
    // Looking into the light (the ray along -z, cos theta = 1), Henyey-Greenstein with g = 0.5
    // scatters 6 times as much; with its extinction 0, none of it is taken away.
    m.phase = PhaseKind::henyey_greenstein;
    m.eccentricity = 0.5f;
    m.extinction = 0;
    const FogEffect forwards = marched(lit_along_z(), m, Ray{{0, 0, 0}, {0, 0, -1}}, 3);
    EXPECT_NEAR(forwards.transmittance.r, std::exp(-0.3f), 1e-6f);
    EXPECT_NEAR(forwards.added.r, 6 * 0.3f * (1 - std::exp(-0.3f)) / 0.1f, 1e-4f);
}

TEST(Media, ADensityVaryingAlongTheRayIsSampledAtTheIntervalsMiddles) {
    // A density of 1 for x < 1 and 0 beyond (a checker of unit cells along x, seen at y = z =
    // 0.5): over [0, 2] with 10 intervals, half the emission 1 of a non-absorbing medium.
    Medium m;
    m.emission = Color::gray(1);
    m.density = {Texture(CheckerTexture{Color::gray(1), Color::gray(0), 1, CheckerSpace::solid})};
    const FogEffect e = marched(lit_along_z(), m, Ray{{0, 0.5f, 0.5f}, {1, 0, 0}}, 2);
    EXPECT_NEAR(e.added.r, 1, 1e-5f);
    EXPECT_EQ(media_transmittance(std::vector<Medium>{m}, Ray{{0, 0.5f, 0.5f}, {1, 0, 0}}, 2),
              (Color{1, 1, 1}));
}

// A sphere of radius 1 filled with a glowing, absorbing medium before a glowing wall, seen
// through its middle along z: the wall's 1 comes through exp(-2 sigma_t), and the medium adds
// e (1 - exp(-2 sigma_t)) / sigma_t.
Scene medium_before_a_wall(IntegratorKind integrator) {
    Scene scene;
    scene.settings.width = scene.settings.height = 4;
    scene.settings.integrator = integrator;
    scene.settings.samples_per_pixel = 4;
    scene.settings.background = {};
    scene.camera.from = {0, 0, -50};
    scene.camera.at = {0, 0, 0};
    scene.camera.fov = 0.05f;
    Material smoke;
    smoke.ka = smoke.kd = smoke.ks = 0;
    smoke.transmit = 1;
    Medium m;
    m.absorption = Color::gray(0.3f);
    m.emission = {0.5f, 0.25f, 0};
    smoke.media = {m};
    scene.materials = {smoke, testing::glowing(Color::gray(1))};
    scene.objects.push_back({Sphere{{0, 0, 0}, 1}, 0});
    scene.objects.push_back({Disk{{0, 0, 3}, {0, 0, -1}, 10}, 1});
    return scene;
}

Color mean_of(const RenderResult& r) {
    Color mean;
    for (const Color& c : r.image.pixels) mean += c / float(r.image.pixels.size());
    return mean;
}

class MediaInside : public ::testing::TestWithParam<IntegratorKind> {};

TEST_P(MediaInside, AnObjectFilledWithAMediumGlowsAndDimsWhatLiesBehind) {
    const Color got = mean_of(render(World(medium_before_a_wall(GetParam())), {}));
    const float t = std::exp(-0.6f), glow = (1 - t) / 0.3f;
    EXPECT_NEAR(got.r, t + 0.5f * glow, 1e-3f);
    EXPECT_NEAR(got.g, t + 0.25f * glow, 1e-3f);
    EXPECT_NEAR(got.b, t, 1e-3f);
}

TEST_P(MediaInside, AHollowObjectInsideHoldsTheMediumAndASolidOneKeepsItOut) {
    // A clear sphere of radius 0.5 in the middle: hollow, the medium fills it too; solid, the
    // ray crosses only the shell from 0.5 to 1 on either side.
    Scene scene = medium_before_a_wall(GetParam());
    Material clear;
    clear.ka = clear.kd = clear.ks = 0;
    clear.transmit = 1;
    clear.hollow = true;
    scene.materials.push_back(clear);
    scene.objects.push_back({Sphere{{0, 0, 0}, 0.5f}, 2});
    const float t = std::exp(-0.6f), glow = (1 - t) / 0.3f;
    EXPECT_NEAR(mean_of(render(World(scene), {})).r, t + 0.5f * glow, 1e-3f);
    scene.materials[2].hollow = false;
    const float shell_t = std::exp(-0.3f), shell_glow = (1 - std::exp(-0.15f)) / 0.3f;
    // Through the near shell (its glow), then the far one (its glow dimmed by the near one).
    const float expected = shell_t + 0.5f * shell_glow * (1 + std::exp(-0.15f));
    EXPECT_NEAR(mean_of(render(World(scene), {})).r, expected, 1e-3f);
}

TEST_P(MediaInside, AScatteringMediumIsLitThroughItsObjectsSurface) {
    // Lit from above, with opaque shadows: the feelers from the medium pass the sphere's clear
    // surface. Scattering 0.1 that extinguishes nothing adds 0.1 x 1 over the chord of 2.
    Scene scene = medium_before_a_wall(GetParam());
    ASSERT_FALSE(scene.settings.transparent_shadows);
    Medium haze;
    haze.scattering = Color::gray(0.1f);
    haze.extinction = 0;
    scene.materials[0].media = {haze};
    scene.lights.push_back(DirectionalLight{{0, -1, 0}, {1, 1, 1}});
    EXPECT_NEAR(mean_of(render(World(scene), {})).r, 1.2f, 1e-3f);
}

INSTANTIATE_TEST_SUITE_P(TheIntegratorsThatMarchMedia, MediaInside,
                         ::testing::Values(IntegratorKind::whitted, IntegratorKind::distributed));

TEST(Media, AShadowFeelerThroughAnAbsorbingMediumIsDimmed) {
    // A floor lit from straight above through a sphere of radius 1 absorbing 0.4: below its
    // middle the light arrives as exp(-0.8).
    Scene scene;
    scene.settings.transparent_shadows = true;
    Material smoke;
    smoke.transmit = 1;
    Medium m;
    m.absorption = Color::gray(0.4f);
    smoke.media = {m};
    scene.materials = {smoke};
    scene.objects.push_back({Sphere{{0, 0, 0}, 1}, 0});
    scene.lights.push_back(PointLight{{0, 10, 0}, {1, 1, 1}});
    const World world(scene);
    ShadowFeelers feelers(world);
    RayStats stats;
    SurfacePoint below;
    below.p = {0, -3, 0};
    const Color lit = feelers.transmittance(0, below, Normal3{0, 1, 0}, {0, 1, 0}, 13, 0, stats);
    EXPECT_NEAR(lit.r, std::exp(-0.8f), 1e-4f);
}

// A glowing wall 10 away through an atmosphere that absorbs 0.1 and glows 0.2 a unit: the wall's
// 1 comes through exp(-1), and the atmosphere adds 0.2 (1 - exp(-1)) / 0.1.
Scene wall_in_an_atmosphere(IntegratorKind integrator) {
    Scene scene;
    scene.settings.width = scene.settings.height = 4;
    scene.settings.integrator = integrator;
    scene.settings.samples_per_pixel = 4;
    scene.settings.background = {};
    scene.camera.from = {0, 0, -10};
    scene.camera.at = {0, 0, 0};
    scene.camera.fov = 0.05f;
    scene.materials = {testing::glowing(Color::gray(1))};
    scene.objects.push_back({Disk{{0, 0, 0}, {0, 0, -1}, 10}, 0});
    Medium air;
    air.absorption = Color::gray(0.1f);
    air.emission = Color::gray(0.2f);
    scene.atmosphere = {air};
    return scene;
}

TEST_P(MediaInside, TheAtmosphereFillsTheSpaceBetweenTheObjects) {
    const Color got = mean_of(render(World(wall_in_an_atmosphere(GetParam())), {}));
    EXPECT_NEAR(got.g, std::exp(-1.0f) + 0.2f * (1 - std::exp(-1.0f)) / 0.1f, 1e-3f);
}

TEST(Media, ALightOutOfTheMediaScattersNothingInThem) {
    // A scattering atmosphere lit by a light that scatters in it, then by one that does not.
    Scene scene = wall_in_an_atmosphere(IntegratorKind::whitted);
    scene.atmosphere[0].emission = {};
    scene.atmosphere[0].scattering = Color::gray(0.05f);
    scene.lights.push_back(PointLight{{0, 5, -5}, {1, 1, 1}});
    const float t = std::exp(-1.5f);  // sigma_t = 0.15 over 10
    EXPECT_GT(mean_of(render(World(scene), {})).r, t + 0.01f);
    std::get<PointLight>(scene.lights[0]).in_media = false;
    EXPECT_NEAR(mean_of(render(World(scene), {})).r, t, 1e-4f);
}

TEST(Media, TheAtmosphereEndsAtTheBoxAroundTheObjectsTheLightsAndTheEye) {
    // The eye at z = -10 and the wall's disk at z = 0 (radius 10): a ray along +z from the eye
    // leaves the box where it meets the wall, one along -x where the box ends at x = -10.
    const World world(wall_in_an_atmosphere(IntegratorKind::whitted));
    EXPECT_NEAR(world.atmosphere_reach(Ray{{0, 0, -10}, {0, 0, 1}}), 10, 1e-4f);
    EXPECT_NEAR(world.atmosphere_reach(Ray{{0, 0, -5}, {-1, 0, 0}}), 10, 1e-4f);
}

}  // namespace
}  // namespace glint
