// Animations (scene/animation.h): frame times, the scene of a frame, and lights moved from frame
// to frame, with worked numbers; the loader's `animation` and light `motion`.
#include "glint/scene/animation.h"

#include <gtest/gtest.h>

#include <string>
#include <variant>

#include "glint/scene/yaml/yaml_scene_loader.h"

namespace glint {
namespace {

Scene parse(const std::string& text) { return parse_yaml_scene(text, "test.yaml"); }

void expect_near(Point3 a, Point3 b) {
    EXPECT_NEAR(a.x, b.x, 1e-5f);
    EXPECT_NEAR(a.y, b.y, 1e-5f);
    EXPECT_NEAR(a.z, b.z, 1e-5f);
}
void expect_near(Vector3 a, Vector3 b) {
    expect_near(Point3(a.x, a.y, a.z), Point3(b.x, b.y, b.z));
}

TEST(Animation, FrameFStartsAtFOverFps) {
    EXPECT_EQ(frame_time({24, 8}, 0), 0);
    EXPECT_EQ(frame_time({24, 8}, 3), 0.375f);
    EXPECT_FLOAT_EQ(frame_time({100, 25}, 50), 2.0f);
}

TEST(Animation, AFrameMovesTheShutterAndPlacesTheLights) {
    const Scene scene = parse(R"(
animation: {frames: 10, fps: 4}
camera: {from: [0, 0, -5], at: [0, 0, 0], shutter: [0.5, 0.625]}
lights:
  - type: point
    position: [1, 2, 3]
    motion:
      - {time: 0}
      - {time: 2, transform: [{translate: [8, 0, 0]}]}
objects: [{type: sphere, center: [0, 0, 0], radius: 1}]
)");
    ASSERT_TRUE(scene.animation);
    EXPECT_EQ(scene.animation->frames, 10);
    EXPECT_EQ(scene.animation->fps, 4);
    // Loaded, the light stands where it is when the shutter opens: 8 * 0.5 / 2 = 2 along x.
    expect_near(std::get<PointLight>(scene.lights[0]).position, {3, 2, 3});
    // Frame 2 starts at 0.5 s: its shutter [1, 1.125], the light 8 * 1 / 2 = 4 along.
    const Scene frame = scene_at_frame(scene, 2);
    EXPECT_EQ(frame.camera.shutter_open, 1.0f);
    EXPECT_EQ(frame.camera.shutter_close, 1.125f);
    expect_near(std::get<PointLight>(frame.lights[0]).position, {5, 2, 3});
    // After the last keyframe the light holds: frame 9 opens at 2.75 s.
    expect_near(std::get<PointLight>(scene_at_frame(scene, 9).lights[0]).position, {9, 2, 3});
    // Frame 0 is the scene as loaded.
    EXPECT_EQ(scene_at_frame(scene, 0).camera.shutter_open, 0.5f);
}

TEST(Animation, FpsDefaultsTo24) {
    const Scene scene = parse(R"(
animation: {frames: 3}
camera: {from: [0, 0, -5], at: [0, 0, 0]}
)");
    ASSERT_TRUE(scene.animation);
    EXPECT_EQ(scene.animation->fps, 24);
    EXPECT_FALSE(parse("camera: {from: [0, 0, -5], at: [0, 0, 0]}").animation);
}

TEST(Animation, MovedLightsTurnWithTheirTransform) {
    const Transform quarter = Transform::rotate({0, 0, 1}, 90);  // x to y
    SpotLight spot;
    spot.position = {1, 0, 0};
    spot.direction = {1, 0, 0};
    const auto moved_spot = std::get<SpotLight>(moved_light(spot, quarter));
    expect_near(moved_spot.position, {0, 1, 0});
    expect_near(moved_spot.direction, {0, 1, 0});
    EXPECT_EQ(moved_spot.cos_cone, spot.cos_cone);

    DirectionalLight sun;
    sun.direction = {1, 0, 0};
    expect_near(std::get<DirectionalLight>(moved_light(sun, quarter)).direction, {0, 1, 0});

    // An area light moves with its shape; scaled evenly by 2, a sphere's radius doubles.
    const Transform grow = Transform::translate({0, 0, 5}) * Transform::scale(2, 2, 2);
    const auto ball = std::get<AreaLight>(moved_light(Light(sphere_light({1, 0, 0}, 0.5f)), grow));
    expect_near(ball.center, {2, 0, 5});
    expect_near(std::get<Sphere>(ball.shape).center, {2, 0, 5});
    EXPECT_FLOAT_EQ(std::get<Sphere>(ball.shape).radius, 1.0f);

    const auto disk = std::get<AreaLight>(
        moved_light(Light(disk_light({0, 0, 0}, Normal3(1, 0, 0), 1)), quarter * grow));
    EXPECT_FLOAT_EQ(std::get<Disk>(disk.shape).radius, 2.0f);
    expect_near(to_vector(std::get<Disk>(disk.shape).normal), {0, 1, 0});

    // A 2 x 1 rectangle turned a quarter about x: its area stays, its corners turn.
    const auto rect =
        std::get<AreaLight>(moved_light(Light(*rectangle_light({0, 0, 0}, {2, 0, 0}, {0, 1, 0})),
                                        Transform::rotate({1, 0, 0}, 90)));
    EXPECT_FLOAT_EQ(std::get<Polygon>(rect.shape).area(), 2.0f);
    expect_near(std::get<Polygon>(rect.shape).vertices[2], {1, 0, 0.5f});
}

TEST(Animation, OnlyEvenScalingKeepsALightsShape) {
    EXPECT_TRUE(keeps_shapes(Transform()));
    EXPECT_TRUE(keeps_shapes(Transform::rotate({1, 2, 3}, 33) * Transform::scale(3, 3, 3)));
    EXPECT_TRUE(keeps_shapes(Transform::scale(-1, 1, 1)));  // a mirror keeps shapes
    EXPECT_FALSE(keeps_shapes(Transform::scale(1, 2, 1)));
    Matrix4 m = Matrix4::identity();
    m.m[0][1] = 0.5f;
    const auto shear = Transform::from_matrix(m);
    ASSERT_TRUE(shear);
    EXPECT_FALSE(keeps_shapes(*shear));
}

TEST(Animation, AMovingAreaLightsFaceMovesWithIt) {
    const Scene scene = parse(R"(
animation: {frames: 2, fps: 1}
camera: {from: [0, 0, -5], at: [0, 0, 0]}
lights:
  - type: sphere
    center: [0, 3, 0]
    radius: 0.5
    motion: [{time: 0}, {time: 1, transform: [{translate: [2, 0, 0]}]}]
)");
    ASSERT_EQ(scene.moving_lights.size(), 1u);
    ASSERT_EQ(scene.objects.size(), 1u);  // the face
    const auto* face = std::get_if<Moving>(&scene.objects[0].shape);
    ASSERT_NE(face, nullptr);
    expect_near(face->motion->at(1)(Point3{0, 3, 0}), {2, 3, 0});
    expect_near(std::get<AreaLight>(scene_at_frame(scene, 1).lights[0]).center, {2, 3, 0});
}

}  // namespace
}  // namespace glint
