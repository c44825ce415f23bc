// Coloured glass that fades inside, and a coloured mirror, seen by every integrator: a glowing
// wall behind a slab whose surfaces filter by its colour (tint) and whose inside fades by
// Beer-Lambert's law, and one reflected in a mirror whose reflection varies with the angle. Each
// integrator follows clear refraction and mirrors alike, so each must see the same worked colour.
#include <gtest/gtest.h>

#include <cmath>

#include "common/under_sanitizer.h"
#include "glint/render/render.h"
#include "scene_parts.h"

namespace glint {
namespace {

// The slab is 1 thick, of colour C = (1, 0.5, 0.25) filtering all it lets through, fading
// with distance 1 towards (0.5, 1, 0). Its index is 1, so rays cross it straight.
Scene glass_before_a_wall(IntegratorKind integrator) {
    Scene scene;
    scene.settings.width = scene.settings.height = 8;
    scene.settings.integrator = integrator;
    scene.settings.samples_per_pixel = 4;
    scene.settings.background = {};
    scene.camera.from = {0, 0, -5};
    scene.camera.at = {0, 0, 0};
    scene.camera.fov = 6;
    Material glass;
    glass.ka = glass.kd = glass.ks = 0;
    glass.transmit = 1;
    glass.tint = 1;
    glass.color = Color{1, 0.5f, 0.25f};
    glass.fade = {1, InteriorFade::kExponential, {0.5f, 1, 0}};
    scene.materials = {glass, testing::glowing(Color::gray(1))};
    scene.objects.push_back({Box{{-3, -3, -0.5f}, {3, 3, 0.5f}}, 0});
    scene.objects.push_back({Disk{{0, 0, 3}, {0, 0, -1}, 10}, 1});
    return scene;
}

class TintedGlass : public ::testing::TestWithParam<IntegratorKind> {};

TEST_P(TintedGlass, LetsThroughTheColourSquaredAndTheFade) {
    const RenderResult r = render(World(glass_before_a_wall(GetParam())), {});
    // Filtered on the way in and on the way out: C^2 = (1, 0.25, 0.0625); faded over the
    // slab's thickness: (exp(-0.5), 1, exp(-1)). The rays at the image's edge cross up to
    // 1 / cos(4.3 degrees) = 1.003 of it.
    const Color expected{std::exp(-0.5f), 0.25f, 0.0625f * std::exp(-1.0f)};
    Color mean;
    for (const Color& c : r.image.pixels) mean += c / float(r.image.pixels.size());
    EXPECT_NEAR(mean.r, expected.r, 0.005f * expected.r);
    EXPECT_NEAR(mean.g, expected.g, 0.005f * expected.g);
    EXPECT_NEAR(mean.b, expected.b, 0.005f * expected.b);
}

// A coloured metallic mirror seen head on, reflecting a glowing wall behind the eye: kr is its
// facing value 0.2 (not the grazing 0.5), in the reflection's colour (1, 0.5, 0.25) and, metallic,
// the surface colour (1, 0.8, 0.6).
TEST_P(TintedGlass, AMirrorHeadOnReflectsItsFacingValueInItsColours) {
    Scene scene = glass_before_a_wall(GetParam());
    Material mirror;
    mirror.ka = mirror.kd = mirror.ks = 0;
    mirror.color = Color{1, 0.8f, 0.6f};
    mirror.reflect = 0.5f;
    mirror.reflect_angular = AngularReflection{0.2f, 1, false};
    mirror.reflect_color = {1, 0.5f, 0.25f};
    mirror.reflect_metallic = 1;
    scene.materials[0] = mirror;
    scene.objects[0] = {Plane{{0, 0, 0}, {0, 0, -1}}, 0};
    scene.objects[1] = {Disk{{0, 0, -10}, {0, 0, 1}, 20}, 1};
    const RenderResult r = render(World(scene), {});
    const Color expected{0.2f, 0.2f * 0.5f * 0.8f, 0.2f * 0.25f * 0.6f};
    Color mean;
    for (const Color& c : r.image.pixels) mean += c / float(r.image.pixels.size());
    EXPECT_NEAR(mean.r, expected.r, 0.005f * expected.r);
    EXPECT_NEAR(mean.g, expected.g, 0.005f * expected.g);
    EXPECT_NEAR(mean.b, expected.b, 0.005f * expected.b);
}

INSTANTIATE_TEST_SUITE_P(EveryIntegratorThatRefracts, TintedGlass,
                         ::testing::Values(IntegratorKind::whitted, IntegratorKind::distributed,
                                           IntegratorKind::path, IntegratorKind::light,
                                           IntegratorKind::photon, IntegratorKind::cone),
                         [](const auto& param) {
                             return std::string(integrator_info(param.param).name);
                         });

}  // namespace
}  // namespace glint
