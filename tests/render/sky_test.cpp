// An image sky: what eye rays that miss see, and what lights a floor open to it, by each
// physically based integrator, against the irradiance integrated from the image.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "glint/math/constants.h"
#include "glint/render/render.h"
#include "global_illumination_scenes.h"

namespace glint {
namespace {

// A dim sky, bluer overhead, with a sun 45 to 67 degrees from the zenith.
SkyImage sunny() {
    auto image = std::make_shared<Image>(16, 8);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 16; ++x)
            image->at(x, y) = {0.2f + 0.01f * float(x), 0.3f, 0.6f - 0.05f * float(y)};
    image->at(5, 2) = {40, 36, 30};
    return {image, 0.4f, {1, 1, 1}};
}

// A white disk of albedo 0.5 open to the sky, seen from above and filling the frame.
Scene floor_under(const SkyImage& sky, IntegratorKind integrator) {
    Scene scene;
    scene.settings.width = scene.settings.height = 8;
    scene.settings.integrator = integrator;
    scene.settings.samples_per_pixel = testing::kUnderSanitizer ? 64 : 256;
    scene.settings.filter = FilterSpec{FilterKind::box, 0.5f};
    scene.camera.from = {0, 5, 0.5f};
    scene.camera.at = {0, 0, 0};
    scene.camera.fov = 20;
    Material floor;
    floor.ka = 0;
    floor.kd = 0.5f;
    scene.materials.push_back(floor);
    scene.objects.push_back({Disk{{0, 0, 0}, {0, 1, 0}, 1.5f}, 0});
    scene.settings.photons.per_pass = 1000;  // the floor's light is all direct: no photon stays
    scene.sky = sky;
    return scene;
}

// (albedo / pi) times the irradiance the sky gives a surface facing up: the midpoint rule over
// (cos theta, phi), uniform in solid angle, of L(w) cos theta.
Color lambert_under(const Sky& sky, float albedo) {
    constexpr int kCells = 512;
    double r = 0, g = 0, b = 0;
    for (int j = 0; j < kCells; ++j) {
        const double c = (j + 0.5) / kCells, s = std::sqrt(1 - c * c);
        for (int i = 0; i < 2 * kCells; ++i) {
            const double phi = (i + 0.5) * kPi / kCells;
            const Color l =
                sky.radiance({float(s * std::cos(phi)), float(c), float(s * std::sin(phi))});
            r += l.r * c;
            g += l.g * c;
            b += l.b * c;
        }
    }
    const double cell = (1.0 / kCells) * (kPi / kCells) * albedo / kPi;
    return {float(r * cell), float(g * cell), float(b * cell)};
}

TEST(SkyImage, EyeRaysThatMissSeeIt) {
    for (const IntegratorKind integrator :
         {IntegratorKind::whitted, IntegratorKind::distributed, IntegratorKind::path,
          IntegratorKind::light, IntegratorKind::photon}) {
        Scene scene;
        scene.settings.width = scene.settings.height = 1;
        scene.settings.integrator = integrator;
        scene.settings.filter = FilterSpec{FilterKind::box, 0.5f};
        scene.camera.from = {0, 0, 0};
        scene.camera.at = {0.3f, 0.2f, -1};
        scene.camera.fov = 0.01f;
        scene.sky = sunny();
        const Sky sky(*scene.sky);
        const Color want = sky.radiance({0.3f, 0.2f, -1});
        const Color got = render(World(scene), {}).image.at(0, 0);
        EXPECT_NEAR(got.r, want.r, 1e-3f * want.r) << integrator_name(integrator);
        EXPECT_NEAR(got.b, want.b, 1e-3f * want.b) << integrator_name(integrator);
    }
}

TEST(SkyImage, LightsAFloorAsTheIrradianceIntegratedFromTheImage) {
    const Color want = lambert_under(Sky(sunny()), 0.5f);
    for (const IntegratorKind integrator :
         {IntegratorKind::path, IntegratorKind::light, IntegratorKind::photon}) {
        SCOPED_TRACE(integrator_name(integrator));
        testing::expect_furnace_answer(render(World(floor_under(sunny(), integrator)), {}).image,
                                       want);
    }
}

TEST(SkyImage, ARoofOverTheFloorShadowsItFromTheSky) {
    // A sky bright within 34 degrees of the zenith (the top row's centre and the next, between
    // which the filter blends) and black elsewhere; a wide roof just above the camera hides it
    // from the floor, whose every path towards the sky then ends on the roof.
    auto overhead = std::make_shared<Image>(16, 8, Color{});
    for (int x = 0; x < 16; ++x) overhead->at(x, 0) = Color::gray(3);
    for (const IntegratorKind integrator :
         {IntegratorKind::path, IntegratorKind::light, IntegratorKind::photon}) {
        SCOPED_TRACE(integrator_name(integrator));
        Scene scene = floor_under({overhead, 0, {1, 1, 1}}, integrator);
        scene.camera.from = {0, 0.9f, 0.1f};
        scene.camera.fov = 60;
        Material roof;
        roof.ka = 0;
        roof.kd = 0.5f;
        scene.materials.push_back(roof);
        scene.objects.push_back({Disk{{0, 1, 0}, {0, 1, 0}, 100}, 1});
        const Image image = render(World(scene), {}).image;
        for (const Color& c : image.pixels) EXPECT_EQ(c, Color{});
    }
}

TEST(SkyImage, OneColourLightsAFloorAsTheBackgroundDid) {
    // A uniform sky of L lights a floor of albedo rho to rho L, as a sky image of one colour
    // does.
    auto flat = std::make_shared<Image>(8, 4, Color{0.4f, 0.8f, 1.2f});
    for (const IntegratorKind integrator :
         {IntegratorKind::path, IntegratorKind::light, IntegratorKind::photon}) {
        SCOPED_TRACE(integrator_name(integrator));
        Scene scene = floor_under({flat, 0, {1, 1, 1}}, integrator);
        testing::expect_furnace_answer(render(World(scene), {}).image, {0.2f, 0.4f, 0.6f});
        scene.sky.reset();
        scene.settings.background = {0.4f, 0.8f, 1.2f};
        testing::expect_furnace_answer(render(World(scene), {}).image, {0.2f, 0.4f, 0.6f});
    }
}

}  // namespace
}  // namespace glint
