// The Whitted integrator against worked numbers: each term of the recursion, shadow feelers,
// the ray-tree cut-offs and the ray counts.
#include "glint/render/integrators/whitted.h"

#include <gtest/gtest.h>

#include <cmath>

#include "glint/math/constants.h"

namespace glint {
namespace {

void expect_near(Color a, Color b, float tol = 1e-5f) {
    EXPECT_NEAR(a.r, b.r, tol);
    EXPECT_NEAR(a.g, b.g, tol);
    EXPECT_NEAR(a.b, b.b, tol);
}

// Camera at z = -5 looking at the origin; a single material, editable per test.
Scene base_scene() {
    Scene scene;
    scene.settings.width = scene.settings.height = 9;
    scene.settings.background = {0.2f, 0.4f, 0.6f};
    scene.camera.from = {0, 0, -5};
    scene.camera.at = {0, 0, 0};
    scene.ambient = Color::gray(0.5f);
    scene.materials.push_back(Material{});
    return scene;
}

// Rays traced by kind, and eye rays that hit.
RayStats counts(std::uint64_t primary, std::uint64_t primary_hits, std::uint64_t shadow,
                std::uint64_t reflected, std::uint64_t refracted) {
    RayStats stats;
    stats.traced = {primary, shadow, reflected, refracted};
    stats.primary_hits = primary_hits;
    return stats;
}

const Ray kEyeRay{{0, 0, -5}, {0, 0, 1}};

TEST(Whitted, MissingRaySeesTheBackground) {
    const Scene scene = base_scene();
    const World world(scene);
    RayStats stats;
    expect_near(WhittedIntegrator(world).trace_eye_ray(kEyeRay, stats), {0.2f, 0.4f, 0.6f});
    EXPECT_EQ(stats, (counts(1, 0, 0, 0, 0)));
}

TEST(Whitted, FogFadesWhatARayBringsTowardsTheFogsColour) {
    // A glowing sphere 4 units ahead through fog of distance 10: T = exp(-0.4) = 0.670320, so
    // the red glow arrives as 0.670320 (1, 0, 0) + 0.329680 (0.3, 0.3, 0.3). A ray that misses
    // crosses endless fog: it sees the fog's colour, not the background.
    Scene scene = base_scene();
    Material& m = scene.materials[0];
    m.ka = m.kd = m.ks = 0;
    m.emission = {1, 0, 0};
    scene.objects.push_back({Sphere{{0, 0, 0}, 1}, 0});
    Fog fog;
    fog.distance = 10;
    fog.color = Color::gray(0.3f);
    scene.fogs.push_back(fog);
    const World world(scene);
    RayStats stats;
    expect_near(WhittedIntegrator(world).trace_eye_ray(kEyeRay, stats),
                {0.670320f + 0.329680f * 0.3f, 0.329680f * 0.3f, 0.329680f * 0.3f});
    const Ray past{{0, 0, -5}, {0, 1, 0}};
    expect_near(WhittedIntegrator(world).trace_eye_ray(past, stats), Color::gray(0.3f));
}

TEST(Whitted, OtherIntegratorsWarnThatTheyDrawNoFog) {
    Scene scene = base_scene();
    scene.fogs.push_back(Fog{});
    EXPECT_TRUE(World(scene).warnings().empty());
    scene.settings.integrator = IntegratorKind::path;
    const World path(scene);
    ASSERT_EQ(path.warnings().size(), 1u);
    EXPECT_EQ(path.warnings()[0],
              "the path integrator draws no fog: fog is drawn by the whitted and distributed "
              "integrators");
}

TEST(Whitted, LocalTermIsAmbientPlusDiffusePlusHighlight) {
    // Light from the eye: at the sphere's front N = L = V, so N.L = H.N = R.V = 1 and
    // I = ka Ia C + IL (kd C + ks) = 0.1*0.5*C + 0.8 * (0.6 C + 0.3).
    Scene scene = base_scene();
    Material& m = scene.materials[0];
    m.color = Color{1, 0.5f, 0.25f};
    m.ka = 0.1f, m.kd = 0.6f, m.ks = 0.3f, m.shininess = 7;
    scene.lights.push_back(DirectionalLight{{0, 0, 1}, Color::gray(0.8f)});
    scene.objects.push_back({Sphere{{0, 0, 0}, 1}, 0});
    for (const Highlight h : {Highlight::blinn, Highlight::phong}) {
        scene.materials[0].highlight = h;
        const World world(scene);
        RayStats stats;
        const Color c = WhittedIntegrator(world).trace_eye_ray(kEyeRay, stats);
        expect_near(c, {0.05f + 0.8f * 0.9f, 0.025f + 0.8f * 0.6f, 0.0125f + 0.8f * 0.45f});
        EXPECT_EQ(stats, (counts(1, 1, 1, 0, 0)));
    }
}

TEST(Whitted, LightBehindTheSurfaceSendsNoFeelerAndAddsNothing) {
    Scene scene = base_scene();
    scene.lights.push_back(DirectionalLight{{0, 0, -1}, Color::gray(1)});
    scene.objects.push_back({Sphere{{0, 0, 0}, 1}, 0});
    const World world(scene);
    RayStats stats;
    expect_near(WhittedIntegrator(world).trace_eye_ray(kEyeRay, stats), Color::gray(0.05f));
    EXPECT_EQ(stats[RayKind::shadow], 0u);
}

// A floor y = 0 seen from above, a point light above it and a small occluder between.
Scene shadow_scene(bool occluder_casts_shadow) {
    Scene scene = base_scene();
    scene.camera.from = {0, 5, 0};
    scene.camera.at = {0, 0, 0};
    scene.camera.up = {0, 0, 1};
    scene.materials[0].ka = 0.2f, scene.materials[0].kd = 0.5f;
    scene.lights.push_back(PointLight{{0, 4, 0}, Color::gray(1)});
    scene.objects.push_back({Plane{{0, 0, 0}, {0, 1, 0}}, 0});
    scene.objects.push_back({Sphere{{0, 2, 0}, 0.1f}, 0, occluder_casts_shadow});
    return scene;
}

TEST(Whitted, ShadowFeelerBlockedLeavesOnlyAmbient) {
    const Scene scene = shadow_scene(true);
    const World world(scene);
    RayStats stats;
    // From just above the floor, under the occluder (an eye ray would hit the occluder).
    const Ray down{{0, 0.05f, 0}, {0, -1, 0}};
    expect_near(WhittedIntegrator(world).trace(down, 2, 1, stats), Color::gray(0.1f));
    EXPECT_EQ(stats[RayKind::shadow], 1u);
}

TEST(Whitted, ObjectThatCastsNoShadowLetsTheLightThrough) {
    const Scene scene = shadow_scene(false);
    const World world(scene);
    RayStats stats;
    const Ray down{{0, 0.05f, 0}, {0, -1, 0}};
    // ka Ia + kd IL (N.L) = 0.1 + 0.5, no attenuation.
    expect_near(WhittedIntegrator(world).trace(down, 2, 1, stats), Color::gray(0.6f));
}

// A light that casts no shadows (POV-Ray's shadowless) sends no feeler: the occluder that does
// cast shadows lets its light through all the same.
TEST(Whitted, ALightWithoutShadowsSendsNoFeeler) {
    Scene scene = shadow_scene(true);
    std::get<PointLight>(scene.lights[0]).casts_shadows = false;
    const World world(scene);
    RayStats stats;
    const Ray down{{0, 0.05f, 0}, {0, -1, 0}};
    expect_near(WhittedIntegrator(world).trace(down, 2, 1, stats), Color::gray(0.6f));
    EXPECT_EQ(stats[RayKind::shadow], 0u);
}

TEST(Whitted, TransparentShadowsMultiplyTheTransmitOfEachSurfaceCrossed) {
    Scene scene = shadow_scene(true);
    scene.settings.transparent_shadows = true;
    Material glass;
    glass.transmit = 0.5f;
    scene.materials.push_back(glass);
    scene.objects[1].material = 1;
    const World world(scene);
    RayStats stats;
    const Ray down{{0, 0.05f, 0}, {0, -1, 0}};
    // The feeler crosses the sphere twice: 0.1 + 0.25 * 0.5.
    expect_near(WhittedIntegrator(world).trace(down, 2, 1, stats), Color::gray(0.225f));
    EXPECT_EQ(stats[RayKind::shadow], 3u);  // to the sphere, through it, and on to the light
}

TEST(Whitted, TransparentShadowsTakeTheTintAndTheFadeOfTheGlassCrossed) {
    // The occluder (radius 0.1) filters by its colour (1, 0.5, 0.25) on the way in and out, and
    // fades over its diameter 0.2 with distance 0.2 towards (0.5, 1, 0): exp(-(1 - c)).
    Scene scene = shadow_scene(true);
    scene.settings.transparent_shadows = true;
    Material glass;
    glass.transmit = 0.5f;
    glass.tint = 1;
    glass.color = Color{1, 0.5f, 0.25f};
    glass.fade = {0.2f, InteriorFade::kExponential, {0.5f, 1, 0}};
    scene.materials.push_back(glass);
    scene.objects[1].material = 1;
    const World world(scene);
    RayStats stats;
    const Ray down{{0, 0.05f, 0}, {0, -1, 0}};
    // 0.1 ambient + 0.5 direct x (0.5 C)^2 x fade.
    const Color crossed =
        Color{0.25f, 0.0625f, 0.015625f} * Color{std::exp(-0.5f), 1, std::exp(-1.0f)};
    expect_near(WhittedIntegrator(world).trace(down, 2, 1, stats),
                Color::gray(0.1f) + 0.5f * crossed, 1e-4f);
}

TEST(Whitted, MirrorAddsKrTimesTheReflectedColour) {
    // A mirror plane facing the eye; the reflected ray goes back past the eye into the sky.
    Scene scene = base_scene();
    Material& m = scene.materials[0];
    m.ka = 0.2f, m.kd = 0, m.reflect = 0.5f;
    scene.objects.push_back({Plane{{0, 0, 0}, {0, 0, -1}}, 0});
    const World world(scene);
    RayStats stats;
    const Color c = WhittedIntegrator(world).trace_eye_ray(kEyeRay, stats);
    expect_near(c, Color::gray(0.1f) + 0.5f * Color{0.2f, 0.4f, 0.6f});
    EXPECT_EQ(stats, (counts(1, 1, 0, 1, 0)));
}

TEST(Whitted, AReflectionVaryingWithTheAngleTakesItsFacingValueHeadOnAndItsColour) {
    // The eye ray meets the mirror head on: kr is the facing 0.2 (not the grazing 0.5), each
    // channel times the reflection's colour (1, 0.5, 0.25).
    Scene scene = base_scene();
    Material& m = scene.materials[0];
    m.ka = 0.2f, m.kd = 0, m.reflect = 0.5f;
    m.reflect_angular = AngularReflection{0.2f, 1, false};
    m.reflect_color = {1, 0.5f, 0.25f};
    scene.objects.push_back({Plane{{0, 0, 0}, {0, 0, -1}}, 0});
    const World world(scene);
    RayStats stats;
    const Color c = WhittedIntegrator(world).trace_eye_ray(kEyeRay, stats);
    expect_near(c, Color::gray(0.1f) + 0.2f * Color{1, 0.5f, 0.25f} * Color{0.2f, 0.4f, 0.6f});
}

// Two parallel mirrors facing each other, the eye between them: the ray bounces until cut.
Scene hall_of_mirrors(float reflect, int max_depth, float min_weight) {
    Scene scene = base_scene();
    scene.settings.max_depth = max_depth;
    scene.settings.min_weight = min_weight;
    Material& m = scene.materials[0];
    m.ka = 0, m.kd = 0, m.emission = Color::gray(1), m.reflect = reflect;
    scene.objects.push_back({Plane{{0, 0, 1}, {0, 0, -1}}, 0});
    scene.objects.push_back({Plane{{0, 0, -6}, {0, 0, 1}}, 0});
    return scene;
}

TEST(Whitted, RayTreeIsCutAtMaxDepth) {
    // Each surface emits 1, so depth d gives 1 + r + r^2 + ... + r^(d-1).
    const Scene scene = hall_of_mirrors(0.5f, 4, 0);
    const World world(scene);
    RayStats stats;
    expect_near(WhittedIntegrator(world).trace_eye_ray(kEyeRay, stats), Color::gray(1.875f));
    EXPECT_EQ(stats[RayKind::reflected], 3u);
}

TEST(Whitted, RayTreeIsCutWhenTheWeightFallsBelowTheMinimum) {
    // Weights 0.5, 0.25, 0.125, 0.0625: a minimum of 0.1 stops after three reflections.
    const Scene scene = hall_of_mirrors(0.5f, 64, 0.1f);
    const World world(scene);
    RayStats stats;
    expect_near(WhittedIntegrator(world).trace_eye_ray(kEyeRay, stats), Color::gray(1.875f));
    EXPECT_EQ(stats[RayKind::reflected], 3u);
}

TEST(Whitted, NormalIncidenceThroughAGlassSphereReachesTheBackground) {
    // Straight through the centre: no bending, kt applies at entry and at exit.
    Scene scene = base_scene();
    Material& m = scene.materials[0];
    m.ka = 0, m.kd = 0, m.transmit = 0.8f, m.ior = 1.5f;
    scene.objects.push_back({Sphere{{0, 0, 0}, 1}, 0});
    const World world(scene);
    RayStats stats;
    expect_near(WhittedIntegrator(world).trace_eye_ray(kEyeRay, stats),
                0.64f * Color{0.2f, 0.4f, 0.6f});
    EXPECT_EQ(stats, (counts(1, 1, 0, 0, 2)));
}

TEST(Whitted, TintedGlassFiltersTheRefractedRayByItsColour) {
    // As above, each crossing also multiplied by the colour C = (1, 0.5, 0.25): 0.64 C^2 bg.
    Scene scene = base_scene();
    Material& m = scene.materials[0];
    m.ka = 0, m.kd = 0, m.transmit = 0.8f, m.ior = 1.5f, m.tint = 1;
    m.color = Color{1, 0.5f, 0.25f};
    scene.objects.push_back({Sphere{{0, 0, 0}, 1}, 0});
    const World world(scene);
    RayStats stats;
    expect_near(WhittedIntegrator(world).trace_eye_ray(kEyeRay, stats),
                0.64f * Color{1, 0.25f, 0.0625f} * Color{0.2f, 0.4f, 0.6f});
    // Half tinted: each crossing weighs kt (0.5 + 0.5 C).
    m.tint = 0.5f;
    const World half(scene);
    expect_near(WhittedIntegrator(half).trace_eye_ray(kEyeRay, stats),
                0.64f * Color{1, 0.5625f, 0.390625f} * Color{0.2f, 0.4f, 0.6f});
}

TEST(Whitted, TheInsideOfFadingGlassFadesWhatCrossesIt) {
    // Through the centre the ray crosses 2 of the sphere's inside. Exponential fade, distance
    // 2 towards (0.5, 1, 0): (exp(-0.5), 1, exp(-1)); with power 2 at the fade distance, half
    // of 1 - c: (0.75, 1, 0.5).
    Scene scene = base_scene();
    Material& m = scene.materials[0];
    m.ka = 0, m.kd = 0, m.transmit = 0.8f, m.ior = 1.5f;
    m.fade = {2, InteriorFade::kExponential, {0.5f, 1, 0}};
    scene.objects.push_back({Sphere{{0, 0, 0}, 1}, 0});
    RayStats stats;
    const Color through = 0.64f * Color{0.2f, 0.4f, 0.6f};
    expect_near(WhittedIntegrator(World(scene)).trace_eye_ray(kEyeRay, stats),
                through * Color{std::exp(-0.5f), 1, std::exp(-1.0f)});
    m.fade.power = 2;
    expect_near(WhittedIntegrator(World(scene)).trace_eye_ray(kEyeRay, stats),
                through * Color{0.75f, 1, 0.5f});
}

TEST(Whitted, TotalInternalReflectionSendsTheTransmittedEnergyToTheReflectedRay) {
    // Inside a glass sphere, a ray meeting the surface at 60 degrees (past the critical angle
    // of 41.8) is reflected with weight kr + kt. Walls emit 1 and the sky is black.
    Scene scene = base_scene();
    scene.settings.background = {};
    scene.settings.max_depth = 2;
    Material& m = scene.materials[0];
    m.ka = 0, m.kd = 0, m.emission = Color::gray(1), m.reflect = 0.1f, m.transmit = 0.7f;
    m.ior = 1.5f;
    scene.objects.push_back({Sphere{{0, 0, 0}, 1}, 0});
    const World world(scene);
    RayStats stats;
    // Along y = -sin 60 the ray meets the surface at (0.5, -0.866), 60 degrees from the normal.
    const Ray inside{{0, -std::sin(radians(60.0f)), 0}, {1, 0, 0}};
    const Color c = WhittedIntegrator(world).trace(inside, 1, 1, stats);
    expect_near(c, Color::gray(1 + 0.8f * 1));
    EXPECT_EQ(stats[RayKind::reflected], 1u);
    EXPECT_EQ(stats[RayKind::refracted], 0u);
}

}  // namespace
}  // namespace glint
