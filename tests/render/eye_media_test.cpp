// The media eye rays start in: a camera under water enters glass from water's index, nested
// solids stack outermost first, a plane's inside is behind it, and what cannot be decided is
// warned about.
#include "glint/render/integrators/eye_media.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "glint/render/explain/explain.h"
#include "glint/render/world.h"

namespace glint {
namespace {

Material clear(float ior) {
    Material m;
    m.ka = m.kd = m.ks = 0;
    m.transmit = 1;
    m.ior = ior;
    return m;
}

// Water up to y = 2 with a glass block up to y = 1 inside it; the camera at `from` looks
// 45 degrees down along +x, so the centre ray at the height 1.5 meets the glass top at
// x = 0.5.
Scene glass_in_water(Point3 from) {
    Scene scene;
    scene.settings.width = scene.settings.height = 9;
    scene.camera.from = from;
    scene.camera.at = from + Vector3{1, -1, 0};
    scene.camera.up = {0, 1, 0};
    scene.materials = {clear(1.333f), clear(1.5f)};
    scene.materials[0].name = "water";
    scene.materials[1].name = "glass";
    scene.objects.push_back({Box{{-10, -5, -10}, {10, 2, 10}}, 0});
    scene.objects.push_back({Box{{-9, -4, -9}, {9, 1, 9}}, 1});
    return scene;
}

bool any_warning_has(const World& world, const std::string& text) {
    return std::any_of(world.warnings().begin(), world.warnings().end(),
                       [&](const std::string& w) { return w.find(text) != std::string::npos; });
}

TEST(EyeMedia, ACameraUnderWaterEntersGlassFromWater) {
    const World world(glass_in_water({0, 1.5f, 0}));
    EXPECT_EQ(world.eye_media().size(), 1);
    EXPECT_EQ(world.eye_media().ior(), 1.333f);
    EXPECT_TRUE(world.warnings().empty());
    // The centre ray meets the glass top entering it: Snell's n1 is water's, 1.333, and with
    // an incidence of 45 degrees sin(refraction) = 1.333 sin 45 / 1.5 = 0.62839.
    const RayTree tree = explain(world, {4, 4, 0, 0});
    ASSERT_FALSE(tree.nodes.empty());
    const RayNode& eye = tree.nodes[0];
    EXPECT_EQ(eye.object, 1u);
    EXPECT_TRUE(eye.entering);
    EXPECT_EQ(eye.n1, 1.333f);
    EXPECT_EQ(eye.n2, 1.5f);
    EXPECT_NEAR(std::sqrt(1 - eye.cos_refracted * eye.cos_refracted), 0.62839f, 1e-4f);
}

TEST(EyeMedia, NestedSolidsStackOutermostFirst) {
    // Inside the glass, which is inside the water: leaving the glass passes into water.
    const World world(glass_in_water({0, 0.5f, 0}));
    const MediumStack& media = world.eye_media();
    ASSERT_EQ(media.size(), 2);
    EXPECT_EQ(media.ior(), 1.5f);
    EXPECT_EQ(media.ior_after_leaving(1, &world.material_of(1)), 1.333f);
    EXPECT_EQ(media.ior_after_leaving(0, &world.material_of(0)), 1.5f);
}

TEST(EyeMedia, AboveTheWaterIsVacuum) {
    const World world(glass_in_water({0, 3, 0}));
    EXPECT_EQ(world.eye_media().size(), 0);
    EXPECT_EQ(world.eye_media().ior(), 1);
}

TEST(EyeMedia, APlanesInsideIsBehindItsNormal) {
    Scene scene = glass_in_water({0, 1.5f, 0});
    scene.objects[0].shape = Plane{{0, 2, 0}, {0, 1, 0}};
    EXPECT_EQ(World(scene).eye_media().ior(), 1.333f);
    scene.objects[0].shape = Plane{{0, 1.2f, 0}, {0, 1, 0}};
    EXPECT_EQ(World(scene).eye_media().size(), 0);
}

TEST(EyeMedia, OnlyRefractingObjectsAreMedia) {
    Scene scene = glass_in_water({0, 1.5f, 0});
    scene.materials[0].transmit = 0;
    EXPECT_EQ(World(scene).eye_media().size(), 0);
}

TEST(EyeMedia, ALensAcrossTheSurfaceIsWarnedAbout) {
    // The lens, 0.5 across, reaches from 1.3 to 2.3 in height: eye rays start in and above the
    // water. They all start in it, as the centre ray does.
    Scene scene = glass_in_water({0, 1.8f, 0});
    scene.camera.lens.radius = 0.5f;
    const World world(scene);
    EXPECT_TRUE(any_warning_has(world,
                                "eye rays start both inside and outside object 0 (box, "
                                "material \"water\")"))
        << (world.warnings().empty() ? "" : world.warnings()[0]);
    EXPECT_EQ(world.eye_media().ior(), 1.333f);
}

TEST(EyeMedia, AnOrthographicWindowAcrossTheSurfaceIsWarnedAbout) {
    Scene scene = glass_in_water({0, 1.8f, 0});
    scene.camera.projection = Projection::orthographic;
    scene.camera.height = 2;
    EXPECT_TRUE(any_warning_has(World(scene), "eye rays start both inside and outside"));
}

TEST(EyeMedia, AnOpenSurfaceAroundTheEyeIsWarnedAbout) {
    // An open tube of water around the camera: no inside to ask about.
    Scene scene = glass_in_water({0, 1.5f, 0});
    scene.objects[0].shape = Cylinder{{-5, 1.5f, 0}, {5, 1.5f, 0}, 1, false};
    const World world(scene);
    EXPECT_TRUE(any_warning_has(world, "which refracts but has no inside to ask about"));
    EXPECT_EQ(world.eye_media().size(), 0);
}

}  // namespace
}  // namespace glint
