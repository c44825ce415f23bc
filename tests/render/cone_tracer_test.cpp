// The cone integrator against what is known: a pixel half covered by a polygon's edge is half
// its colour; a cone's soft shadow under a disk light against the penumbra integral; glossy cones
// widen with roughness; and its image of spheres and polygons against a 1024-sample jittered
// render of the same scene, much closer than one ray a pixel comes.
#include "glint/render/integrators/cone_tracer.h"

#include <gtest/gtest.h>

#include <cmath>

#include "glint/math/constants.h"
#include "glint/render/render.h"
#include "reference_values.h"
#include "scene_parts.h"

namespace glint {
namespace {

using testing::penumbra_by_integration;
using testing::rms_difference;

using testing::glowing;
using testing::polygon;

TEST(ConeTracer, APixelHalfCoveredByAnEdgeIsHalfItsColour) {
    // A white square whose edge runs down the middle of pixel (1, 1) of a 3 x 3 image, on black.
    Scene scene;
    scene.settings.width = scene.settings.height = 3;
    scene.settings.integrator = IntegratorKind::cone;
    scene.settings.background = {0, 0, 0};
    scene.camera.from = {0, 0, 0};
    scene.camera.at = {0, 0, 1};
    scene.materials = {glowing({1, 1, 1})};
    scene.objects.push_back({polygon({{0, -5, 5}, {-5, -5, 5}, {-5, 5, 5}, {0, 5, 5}}), 0});
    const Image image = render(World(scene), {}).image;
    EXPECT_NEAR(image.at(1, 1).r, 0.5f, 1e-3f);
    // The pixels beside it: all or nothing.
    EXPECT_NEAR(image.at(0, 1).r + image.at(2, 1).r, 1, 1e-3f);
}

TEST(ConeTracer, SoftShadowOfADiskLightMatchesThePenumbraIntegral) {
    Scene scene;
    scene.settings.integrator = IntegratorKind::cone;
    Material floor;
    floor.ka = 0, floor.kd = 1, floor.ks = 0;
    scene.materials = {floor, Material{}};
    scene.objects.push_back({Plane{{0, 0, 0}, {0, 1, 0}}, 0});
    scene.objects.push_back({Disk{{0, 2, 0}, {0, 1, 0}, 0.5f, 0}, 1});
    scene.lights.push_back(disk_light({0, 4, 0}, {0, -1, 0}, 1));
    const World world(scene);
    ConeIntegrator cone(world);
    RayStats stats;
    for (const float x : {0.0f, 0.5f, 1.0f, 1.5f, 2.5f}) {
        // A narrow cone straight down onto the floor point.
        const Ray down{{x, 1, 0}, {0, -1, 0}};
        const Color c = cone.trace({down.origin, down.direction, 1e-4f, 0}, down,
                                   ConeIntegrator::kNone, 1, 1, stats, kVacuum);
        // The disk light and occluder of distributed_test's penumbra (reference_values.h). The cone
        // sees the part of the light the occluder leaves, lit by N.L at its centre;
        // the integral weighs N.L across the light: within 0.02 (0.016 at x = 1.5).
        EXPECT_NEAR(c.r, penumbra_by_integration(x), 0.02) << "x = " << x;
    }
}

// Spheres, a triangle and a square over a plane, on a dark sky, lit by a point light.
Scene spheres_and_polygons(IntegratorKind integrator, int samples) {
    Scene scene;
    scene.settings.width = 64;
    scene.settings.height = 48;
    scene.settings.integrator = integrator;
    scene.settings.samples_per_pixel = samples;
    scene.settings.sampler = samples > 1 ? SamplerKind::jittered : SamplerKind::regular;
    scene.settings.filter = FilterSpec{FilterKind::box, 0.5f};  // a pixel is its area's mean
    scene.settings.background = {0.1f, 0.1f, 0.2f};
    scene.camera.from = {0, 2, -6};
    scene.camera.at = {0, 0.6f, 0};
    scene.camera.fov = 45;
    Material white, red, mirror;
    white.color = Color{0.9f, 0.9f, 0.9f};
    red.color = Color{0.9f, 0.2f, 0.1f};
    mirror.kd = 0.1f;
    mirror.reflect = 0.8f;
    scene.materials = {white, red, mirror};
    scene.objects.push_back({Plane{{0, 0, 0}, {0, 1, 0}}, 0});
    scene.objects.push_back({Sphere{{-1.2f, 0.8f, 0}, 0.8f}, 2});
    scene.objects.push_back({Sphere{{1.1f, 0.5f, -1}, 0.5f}, 1});
    scene.objects.push_back({Triangle{{{{0.2f, 0, 1}, {2.2f, 0, 1.5f}, {1.2f, 1.8f, 1.2f}}}}, 1});
    scene.objects.push_back({polygon({{-0.4f, 0.01f, -2.5f},
                                      {0.4f, 0.01f, -2.5f},
                                      {0.4f, 0.01f, -1.7f},
                                      {-0.4f, 0.01f, -1.7f}}),
                             1});
    PointLight light;
    light.position = {-3, 6, -4};
    scene.lights = {light};
    return scene;
}

TEST(ConeTracer, OneConeAPixelComesCloserToSupersamplingThanOneRay) {
    const Image reference =
        render(World(spheres_and_polygons(IntegratorKind::whitted, 1024)), {}).image;
    const Image ray = render(World(spheres_and_polygons(IntegratorKind::whitted, 1)), {}).image;
    const Image cone = render(World(spheres_and_polygons(IntegratorKind::cone, 1)), {}).image;
    const float ray_error = rms_difference(ray, reference);
    // Half the error here (0.013 against 0.026): the edges and the shadows' edges blend; what
    // remains is where shapes overlap within a pixel, their coverages taken as independent.
    EXPECT_LT(rms_difference(cone, reference), 0.6f * ray_error) << "one ray: " << ray_error;
}

TEST(ConeTracer, GlossyConesWidenWithRoughness) {
    // A mirror floor reflecting a white square's edge: the rougher the floor, the wider the
    // reflected cones and the more pixels the reflected edge blurs over.
    auto blurred_pixels = [](float roughness) {
        Scene scene;
        scene.settings.width = 64;
        scene.settings.height = 48;
        scene.settings.integrator = IntegratorKind::cone;
        scene.settings.background = {0, 0, 0};
        scene.camera.from = {0, 1, -4};
        scene.camera.at = {0, 0, 0};
        Material floor;
        floor.ka = floor.kd = floor.ks = 0;
        floor.reflect = 1;
        floor.roughness = roughness;
        scene.materials = {floor, glowing({1, 1, 1})};
        scene.objects.push_back({Plane{{0, 0, 0}, {0, 1, 0}}, 0});
        scene.objects.push_back({polygon({{0, 0.5f, 2}, {-4, 0.5f, 2}, {-4, 3, 2}, {0, 3, 2}}), 1});
        const Image image = render(World(scene), {}).image;
        int blurred = 0;
        for (int y = image.height / 2; y < image.height; ++y)  // the floor's half
            for (int x = 0; x < image.width; ++x)
                blurred += image.at(x, y).r > 0.05f && image.at(x, y).r < 0.95f;
        return blurred;
    };
    const int sharp = blurred_pixels(0), glossy = blurred_pixels(0.1f),
              rougher = blurred_pixels(0.3f);
    EXPECT_LT(sharp, glossy);
    EXPECT_LT(glossy, rougher);
}

}  // namespace
}  // namespace glint
