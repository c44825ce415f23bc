// Transforms, CSG and instances in the YAML format: what the loader builds from them.
#include <gtest/gtest.h>

#include <variant>

#include "glint/scene/yaml/yaml_scene_loader.h"

namespace glint {
namespace {

constexpr const char* kCamera = "camera: {from: [0, 0, -5], at: [0, 0, 0]}\n";

Scene parse(const std::string& text) { return parse_yaml_scene(kCamera + text, "test.yaml"); }

void expect_near(Point3 a, Point3 b) {
    EXPECT_NEAR(a.x, b.x, 1e-5f);
    EXPECT_NEAR(a.y, b.y, 1e-5f);
    EXPECT_NEAR(a.z, b.z, 1e-5f);
}

TEST(YamlPlacement, TransformStepsApplyInTheWrittenOrder) {
    // Scale by 2, then turn a quarter about z, then move up 1: (1, 0, 0) -> (2, 0, 0) ->
    // (0, 2, 0) -> (0, 3, 0).
    const Scene scene = parse(R"(objects:
  - type: sphere
    center: [0, 0, 0]
    radius: 1
    transform:
      - scale: 2
      - rotate: {axis: [0, 0, 1], angle: 90}
      - translate: [0, 1, 0]
)");
    const auto& placed = std::get<Transformed>(scene.objects[0].shape);
    expect_near(placed.world_from_object(Point3{1, 0, 0}), {0, 3, 0});
    EXPECT_TRUE(std::holds_alternative<Sphere>(*placed.shape));
}

TEST(YamlPlacement, EulerAnglesTurnAboutXThenYThenZ) {
    const Scene scene = parse(R"(objects:
  - {type: sphere, center: [0, 0, 0], radius: 1, transform: [{rotate: [90, 90, 0]}]}
)");
    const auto& placed = std::get<Transformed>(scene.objects[0].shape);
    // (0, 1, 0) -> about x: (0, 0, 1) -> about y: (1, 0, 0).
    expect_near(placed.world_from_object(Point3{0, 1, 0}), {1, 0, 0});
}

TEST(YamlPlacement, MatrixIsRowMajorWithTranslationInTheLastColumn) {
    const Scene scene = parse(R"(objects:
  - type: sphere
    center: [0, 0, 0]
    radius: 1
    transform: [{matrix: [[1, 0, 0, 5], [0, 2, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]}]
)");
    const auto& placed = std::get<Transformed>(scene.objects[0].shape);
    expect_near(placed.world_from_object(Point3{1, 1, 1}), {6, 2, 1});
}

TEST(YamlPlacement, CsgFoldsItsOperandsFromTheLeft) {
    const Scene scene = parse(R"(objects:
  - type: difference
    objects:
      - {type: box, min: [-1, -1, -1], max: [1, 1, 1]}
      - {type: sphere, center: [0, 0, 0], radius: 1.2}
      - {type: sphere, center: [2, 0, 0], radius: 1.5, transform: [{scale: [1, 2, 1]}]}
)");
    const auto& outer = std::get<Csg>(scene.objects[0].shape);
    EXPECT_EQ(outer.operation, CsgOperation::difference);
    EXPECT_TRUE(std::holds_alternative<Transformed>(*outer.b));
    const auto& inner = std::get<Csg>(*outer.a);
    EXPECT_TRUE(std::holds_alternative<Box>(*inner.a));
    EXPECT_TRUE(std::holds_alternative<Sphere>(*inner.b));
}

TEST(YamlPlacement, InstancesShareTheDefinedShapeAndComposeTransforms) {
    const Scene scene = parse(R"(define:
  pillar:
    type: merge
    objects:
      - {type: box, min: [-0.2, 0, -0.2], max: [0.2, 2, 0.2]}
      - {type: sphere, center: [0, 2, 0], radius: 0.3}
  tall-pillar: {type: instance, of: pillar, transform: [{scale: [1, 2, 1]}]}
objects:
  - {type: instance, of: pillar, transform: [{translate: [-2, 0, 0]}]}
  - {type: instance, of: pillar, transform: [{translate: [2, 0, 0]}]}
  - {type: instance, of: tall-pillar, transform: [{translate: [0, 0, 3]}]}
)");
    ASSERT_EQ(scene.objects.size(), 3u);
    const auto& a = std::get<Transformed>(scene.objects[0].shape);
    const auto& b = std::get<Transformed>(scene.objects[1].shape);
    EXPECT_EQ(a.shape.get(), b.shape.get());  // one pillar, placed twice
    const auto& c = std::get<Transformed>(scene.objects[2].shape);
    EXPECT_EQ(c.shape.get(), a.shape.get());  // the instance of an instance composes
    expect_near(c.world_from_object(Point3{0, 1, 0}), {0, 2, 3});
}

}  // namespace
}  // namespace glint
