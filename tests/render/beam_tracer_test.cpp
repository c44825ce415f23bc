// The beam integrator against what is known: a pixel half covered by a polygon's edge is exactly
// half its colour; a square seen through a glass slab at its paraxial apparent distance; and its
// image of a polygonal scene with mirrors and shadows against a 1024-sample jittered render of
// the same scene, much closer than one ray a pixel comes.
#include "glint/render/integrators/beam_tracer.h"

#include <gtest/gtest.h>

#include <cmath>

#include "glint/math/constants.h"
#include "glint/render/render.h"
#include "glint/scene/integrator_fit.h"
#include "reference_values.h"
#include "scene_parts.h"

namespace glint {
namespace {

using testing::rms_difference;

using testing::glowing;
using testing::polygon;

// The beam integrator's square image of size pixels from a camera at the origin looking down
// +z, on black.
Scene looking_down_z(int size) {
    Scene scene;
    scene.settings.width = scene.settings.height = size;
    scene.settings.integrator = IntegratorKind::beam;
    scene.settings.background = {0, 0, 0};
    scene.camera.from = {0, 0, 0};
    scene.camera.at = {0, 0, 1};
    return scene;
}

// A white square's edge at x = x_edge.
Scene edge_scene(int size, float x_edge) {
    Scene scene = looking_down_z(size);
    scene.materials = {glowing({1, 1, 1})};
    scene.objects.push_back(
        {polygon({{x_edge, -5, 5}, {-5, -5, 5}, {-5, 5, 5}, {x_edge, 5, 5}}), 0});
    return scene;
}

TEST(BeamTracer, APixelHalfCoveredByAnEdgeIsExactlyHalfItsColour) {
    // The edge runs down the middle of pixel (1, 1) of a 3 x 3 image.
    const Image image = render(World(edge_scene(3, 0)), {}).image;
    EXPECT_NEAR(image.at(1, 1).r, 0.5f, 1e-5f);
    // Nothing beside it: the (un-mirrored) left of the scene is the image's left or right.
    EXPECT_NEAR(image.at(0, 1).r + image.at(2, 1).r, 1, 1e-5f);
}

TEST(BeamTracer, CoverageFollowsTheEdgeToAFractionOfAPixel) {
    // fov 90 over 8 pixels: x / z = 1 is 4 pixels from the centre. The edge at x / z = 0.3125 +
    // 0.1 / 4 sits 0.1 of a pixel into pixel 5 (or 2, mirrored).
    const float x = 5 * (0.25f + 0.1f / 4);
    Scene scene = edge_scene(8, x);
    scene.camera.fov = 90;
    const Image image = render(World(scene), {}).image;
    float row = 0;
    for (int i = 0; i < 8; ++i) row += image.at(i, 4).r;
    // The square covers 4 + 1 + 0.1 pixels of the row.
    EXPECT_NEAR(row, 5.1f, 1e-4f);
}

TEST(BeamTracer, GlassSlabShowsASquareAtItsParaxialApparentDistance) {
    // A slab of glass (n = 1.5) from z = 2 to 3 in front of a glowing square of half-width 1 at
    // z = 5. Paraxially, depth beyond a plane appears scaled by n1 / n2: the square appears at
    // 2 + (1 + 2 * 1.5) / 1.5 = 4.667, not 5, and so wider.
    Scene scene = looking_down_z(64);
    scene.camera.fov = 60;
    Material glass;
    glass.ka = glass.kd = glass.ks = 0;
    glass.transmit = 1;
    glass.ior = 1.5f;
    scene.materials = {glass, glowing({1, 1, 1})};
    scene.objects.push_back({Box{{-20, -20, 2}, {20, 20, 3}}, 0});
    scene.objects.push_back({polygon({{-1, -1, 5}, {1, -1, 5}, {1, 1, 5}, {-1, 1, 5}}), 1});
    const Image image = render(World(scene), {}).image;
    float row = 0;
    for (int i = 0; i < 64; ++i) row += image.at(i, 32).r;
    const double apparent = 2 + (1 + 2 * 1.5) / 1.5;
    const double expected = 2 * (1 / apparent) / std::tan(kPi / 6) * 32;
    EXPECT_NEAR(row, expected, 1e-3);
    EXPECT_GT(row, 2 * (1 / 5.0) / std::tan(kPi / 6) * 32 + 1);  // wider than without glass
}

// A floor, a wall, two mirrors at an angle, boxes and a non-convex star, lit by a point light:
// polygons only, in every combination the beam tracer meets (mirror images of mirror images,
// shadows across polygons).
Scene polygon_room(IntegratorKind integrator, int samples) {
    Scene scene;
    scene.settings.width = 64;
    scene.settings.height = 48;
    scene.settings.integrator = integrator;
    scene.settings.samples_per_pixel = samples;
    scene.settings.sampler = samples > 1 ? SamplerKind::jittered : SamplerKind::regular;
    scene.settings.filter = FilterSpec{FilterKind::box, 0.5f};  // a pixel is its area's mean
    scene.settings.background = {0.1f, 0.1f, 0.2f};
    scene.settings.max_depth = 4;
    scene.camera.from = {0.5f, 2.2f, -6.5f};
    scene.camera.at = {0, 1, 0};
    scene.camera.fov = 45;
    Material white, red, mirror;
    white.color = Color{0.9f, 0.9f, 0.9f};
    red.color = Color{0.9f, 0.2f, 0.1f};
    red.ks = 0.4f;
    mirror.kd = 0.1f;
    mirror.reflect = 0.8f;
    scene.materials = {white, red, mirror};
    scene.objects.push_back({polygon({{-4, 0, -4}, {4, 0, -4}, {4, 0, 4}, {-4, 0, 4}}), 0});
    scene.objects.push_back({polygon({{-4, 0, 4}, {4, 0, 4}, {4, 4, 4}, {-4, 4, 4}}), 0});
    scene.objects.push_back(
        {polygon({{-3.9f, 0.2f, 3.5f}, {-1.5f, 0.2f, 3.9f}, {-1.5f, 3, 3.9f}, {-3.9f, 3, 3.5f}}),
         2});
    scene.objects.push_back(
        {polygon({{-3.9f, 0.2f, -1}, {-3.6f, 0.2f, 3}, {-3.6f, 3, 3}, {-3.9f, 3, -1}}), 2});
    scene.objects.push_back({Box{{-1.8f, 0, 0.5f}, {-0.8f, 1.6f, 1.5f}}, 1});
    scene.objects.push_back({Box{{1.2f, 0, 1.2f}, {2.4f, 0.8f, 2.4f}}, 0});
    scene.objects.push_back({polygon({{2.6f, 1.2f, 3.95f},
                                      {3.1f, 2.7f, 3.95f},
                                      {3.6f, 1.2f, 3.95f},
                                      {2.3f, 2.2f, 3.95f},
                                      {3.9f, 2.2f, 3.95f}}),
                             1});
    scene.objects.push_back({Triangle{{{{0, 0, -0.5f}, {1.6f, 0, 0.4f}, {0.6f, 1.4f, 0}}}}, 1});
    PointLight light;
    light.position = {-3, 5, -3};
    scene.lights = {light};
    return scene;
}

TEST(BeamTracer, ImageOfPolygonsAndMirrorsMatchesSupersampling) {
    const Image reference = render(World(polygon_room(IntegratorKind::whitted, 1024)), {}).image;
    const Image ray = render(World(polygon_room(IntegratorKind::whitted, 1)), {}).image;
    const Image beam = render(World(polygon_room(IntegratorKind::beam, 1)), {}).image;
    const float ray_error = rms_difference(ray, reference);
    const float beam_error = rms_difference(beam, reference);
    // 0.00034 against 0.040, 120 times closer: what remains is the reference's own error (1024
    // samples) and shading once per fragment of a pixel, where the reference varies Phong's
    // terms across it.
    EXPECT_LT(beam_error, 0.02f * ray_error) << "one ray: " << ray_error;
    EXPECT_LT(beam_error, 0.001f);
}

TEST(BeamTracer, ShadowEdgesAreExactToo) {
    // A white floor seen from straight above, over 3 x 3 pixels of 2.76 units; a wall out of view
    // at x = 6, 6 high, and a light at (20, 20, 0): the wall's top edge casts the shadow's edge
    // along x = 0, down the middle of the centre column (shadowed towards the wall).
    Scene scene;
    scene.settings.width = scene.settings.height = 3;
    scene.settings.integrator = IntegratorKind::beam;
    scene.camera.from = {0, 10, 0};
    scene.camera.at = {0, 0, 0};
    scene.camera.up = {0, 0, 1};
    scene.ambient = {0, 0, 0};
    Material floor;
    floor.ka = 0, floor.kd = 1, floor.ks = 0;
    scene.materials = {floor};
    scene.objects.push_back({polygon({{-9, 0, -9}, {9, 0, -9}, {9, 0, 9}, {-9, 0, 9}}), 0});
    scene.objects.push_back({polygon({{6, 0, -9}, {6, 6, -9}, {6, 6, 9}, {6, 0, 9}}), 0});
    scene.lights.push_back(PointLight{{20, 20, 0}, {1, 1, 1}, {}});
    const Image image = render(World(scene), {}).image;
    // Shaded at the pixel's centre, the origin: N.L = cos 45 degrees, half of the pixel lit.
    EXPECT_NEAR(image.at(1, 1).r, 0.5f * std::sqrt(0.5f), 1e-4f);
    const float left = image.at(0, 1).r, right = image.at(2, 1).r;
    EXPECT_EQ(std::min(left, right), 0);  // the shadowed side
    EXPECT_GT(std::max(left, right), 0.5f);
}

TEST(BeamTracer, CurvedShapesAreRefusedWithTheObjectNamed) {
    Scene scene = edge_scene(4, 0);
    scene.objects.push_back({Sphere{{0, 0, 3}, 1}, 0});
    scene.sources.file = "room.yaml";
    scene.sources.objects = {{3, 5}, {7, 5}};
    try {
        check_integrator_fits(scene);
        FAIL() << "a sphere was accepted";
    } catch (const SceneError& e) {
        EXPECT_EQ(e.location().line, 7);
        EXPECT_NE(std::string(e.what()).find("object 1 is a sphere, which is curved"),
                  std::string::npos)
            << e.what();
    }
}

TEST(BeamTracer, ALensAndFresnelsWeightsAreRefused) {
    Scene lens = edge_scene(4, 0);
    lens.camera.lens.radius = 0.1f;
    EXPECT_THROW(check_integrator_fits(lens), SceneError);
    Scene fresnel = edge_scene(4, 0);
    fresnel.materials[0].transmit = 1;
    fresnel.materials[0].fresnel = true;
    EXPECT_THROW(check_integrator_fits(fresnel), SceneError);
    Scene plane = edge_scene(4, 0);
    plane.objects.push_back({Plane{{0, 0, 0}, {0, 1, 0}}, 0});
    EXPECT_THROW(check_integrator_fits(plane), SceneError);
    // Transformed polygons and meshes are welcome.
    Scene placed = edge_scene(4, 0);
    placed.objects.push_back(
        {Transformed(Transform::translate({0, 1, 0}), std::make_shared<const Shape>(Box{})), 0});
    EXPECT_NO_THROW(check_integrator_fits(placed));
}

}  // namespace
}  // namespace glint
