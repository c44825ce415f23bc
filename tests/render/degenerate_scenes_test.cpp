// Scenes that are valid but numerically hard render without a NaN or infinite sample: coincident
// surfaces, a plane through the eye (its rays run parallel to it), a light on a surface, glass
// spheres nested on one centre, radii of 1e-30 and 1e30 (the camera inside), under both
// integrators.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "glint/render/render.h"
#include "glint/render/world.h"
#include "glint/scene/yaml/yaml_scene_loader.h"

namespace glint {
namespace {

const std::string kHeader = R"(
camera: {from: [0, 1, -5], at: [0, 1, 0], fov: 50}
materials:
  white: {color: [0.9, 0.9, 0.9], kd: 0.8, ks: 0.3, shininess: 40}
  mirror: {color: [1, 1, 1], kd: 0.1, reflect: 0.9}
  glass: {color: [1, 1, 1], kd: 0, ks: 0.5, shininess: 200, reflect: 0.05, transmit: 0.95, ior: 1.5}
lights:
  - {type: point, position: [0, 0, 0], color: [1, 1, 1]}
  - {type: rectangle, center: [0, 3, 0], u: [1, 0, 0], v: [0, 0, 1], color: [0.5, 0.5, 0.5]}
objects:
  # Two coincident spheres and a box whose face lies in the floor.
  - {type: sphere, center: [-1.5, 1, 0], radius: 1, material: white}
  - {type: sphere, center: [-1.5, 1, 0], radius: 1, material: mirror}
  - {type: plane, point: [0, 0, 0], normal: [0, 1, 0], material: white}
  - {type: box, min: [0.5, 0, -0.5], max: [1.5, 1, 0.5], material: mirror}
  # A plane through the eye: the rays that run along it.
  - {type: plane, point: [0, 1, -5], normal: [1, 0, 0], material: white}
  # Glass spheres on one centre, the inner one touching nothing.
  - {type: sphere, center: [0, 1.5, 1], radius: 0.5, material: glass}
  - {type: sphere, center: [0, 1.5, 1], radius: 0.25, material: glass}
  - {type: sphere, center: [0, 1.5, 1], radius: 1e-30, material: glass}
)";

void expect_no_bad_samples(const std::string& text, const std::string& what) {
    for (const std::string integrator : {"whitted", "distributed"}) {
        const std::string image = "image: {width: 40, height: 30, integrator: " + integrator +
                                  (integrator == "distributed" ? ", samples: 4" : "") + "}\n";
        const World world(parse_yaml_scene(image + text, what + ".yaml"));
        const RenderResult result = render(world, RenderOptions{});
        EXPECT_EQ(result.bad_samples.count, 0u) << what << ", " << integrator;
        for (const Color& c : result.image.pixels)
            ASSERT_TRUE(std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b))
                << what << ", " << integrator;
    }
}

TEST(DegenerateScenes, RenderWithoutBadSamples) {
    expect_no_bad_samples(kHeader, "coincident");
    // The camera inside a sphere of radius 1e30 (its inside faces the camera), and one of 1e-30.
    expect_no_bad_samples(
        kHeader + "  - {type: sphere, center: [0, 0, 0], radius: 1e30, material: white}\n", "huge");
}

// An object reaching far out (here a box 10^5 across, as an unbounded quadric cut far out) does
// not set how far every ray leaves its surface: a small sphere's shadow stays on the floor
// beside it. With the far box's 10^5 setting it, feelers started 2 units up and missed the
// sphere.
TEST(DegenerateScenes, AFarObjectLeavesRayOffsetsAlone) {
    const std::string text = R"(
camera: {from: [0, 1, -5], at: [0, 0, 0], fov: 50}
materials:
  white: {color: [0.9, 0.9, 0.9], kd: 0.8}
lights:
  - {type: point, position: [0, 10, 0], color: [1, 1, 1]}
objects:
  - {type: plane, point: [0, 0, 0], normal: [0, 1, 0], material: white}
  - {type: sphere, center: [0, 0.6, 0], radius: 0.5, material: white}
  - {type: box, min: [-1e5, -1e5, 1e5], max: [1e5, 1e5, 1.1e5], material: white}
)";
    const World world(parse_yaml_scene(text, "far.yaml"));
    EXPECT_NEAR(world.ray_epsilon(Point3{0, 0, 0}), 1e-5f * 5, 1e-7f);  // the eye's magnitude
    EXPECT_NEAR(world.ray_epsilon(Point3{1e5f, 0, 0}), 1, 1e-5f);       // far points their own
    // Right under the sphere, the floor is in its shadow.
    const Point3 floor{0, 0, 0};
    const Vector3 up{0, 1, 0};
    const Ray feeler = world.spawn_ray(floor, Normal3{0, 1, 0}, up);
    EXPECT_TRUE(world.occluded(feeler, {0, 10}, kVisibleToShadowRays));
}

}  // namespace
}  // namespace glint
