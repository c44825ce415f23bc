// Transforms, CSG and instances in the YAML format: what the loader builds from them.
#include <gtest/gtest.h>

#include <string>
#include <variant>
#include <vector>

#include "glint/scene/yaml/yaml_scene_loader.h"

namespace glint::yaml_placement_test {

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
    expect_near(placed.world_from_object()(Point3{1, 0, 0}), {0, 3, 0});
    EXPECT_TRUE(std::holds_alternative<Sphere>(*placed.shape));
}

TEST(YamlPlacement, EulerAnglesTurnAboutXThenYThenZ) {
    const Scene scene = parse(R"(objects:
  - {type: sphere, center: [0, 0, 0], radius: 1, transform: [{rotate: [90, 90, 0]}]}
)");
    const auto& placed = std::get<Transformed>(scene.objects[0].shape);
    // (0, 1, 0) -> about x: (0, 0, 1) -> about y: (1, 0, 0).
    expect_near(placed.world_from_object()(Point3{0, 1, 0}), {1, 0, 0});
}

TEST(YamlPlacement, MatrixIsRowMajorWithTranslationInTheLastColumn) {
    const Scene scene = parse(R"(objects:
  - type: sphere
    center: [0, 0, 0]
    radius: 1
    transform: [{matrix: [[1, 0, 0, 5], [0, 2, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]}]
)");
    const auto& placed = std::get<Transformed>(scene.objects[0].shape);
    expect_near(placed.world_from_object()(Point3{1, 1, 1}), {6, 2, 1});
}

// A difference of [a, b, c] is a minus the merge of b and c, which is (a - b) - c.
TEST(YamlPlacement, DifferenceTakesTheMergeOfTheOperandsAfterTheFirst) {
    const Scene scene = parse(R"(objects:
  - type: difference
    objects:
      - {type: box, min: [-1, -1, -1], max: [1, 1, 1]}
      - {type: sphere, center: [0, 0, 0], radius: 1.2}
      - {type: sphere, center: [2, 0, 0], radius: 1.5, transform: [{scale: [1, 2, 1]}]}
)");
    const auto& outer = std::get<Csg>(scene.objects[0].shape);
    EXPECT_EQ(outer.operation, CsgOperation::difference);
    EXPECT_TRUE(std::holds_alternative<Box>(*outer.a));
    const auto& carved = std::get<Csg>(*outer.b);
    EXPECT_EQ(carved.operation, CsgOperation::merge);
    EXPECT_TRUE(std::holds_alternative<Sphere>(*carved.a));
    EXPECT_TRUE(std::holds_alternative<Transformed>(*carved.b));
}

// A clip of [a, b, c] clips a by the intersection of b and c; a may be an open surface.
TEST(YamlPlacement, ClipCutsTheFirstByTheIntersectionOfTheRest) {
    const Scene scene = parse(R"(objects:
  - type: clip
    objects:
      - {type: disk, center: [0, 0, 0], normal: [0, 1, 0], radius: 2}
      - {type: plane, point: [0, 0, 0], normal: [1, 0, 0]}
      - {type: sphere, center: [0, 0, 0], radius: 1.5}
)");
    const auto& clip = std::get<Csg>(scene.objects[0].shape);
    EXPECT_EQ(clip.operation, CsgOperation::clip);
    EXPECT_TRUE(std::holds_alternative<Disk>(*clip.a));
    EXPECT_EQ(std::get<Csg>(*clip.b).operation, CsgOperation::intersection);
    // The disk is kept where x < 0 and within 1.5 of the centre.
    const Shape& s = scene.objects[0].shape;
    EXPECT_TRUE(intersect(s, Ray{{-1, 1, 0}, {0, -1, 0}}, {0, kInfinity}).has_value());
    EXPECT_FALSE(intersect(s, Ray{{1, 1, 0}, {0, -1, 0}}, {0, kInfinity}).has_value());
    EXPECT_FALSE(intersect(s, Ray{{-1.8f, 1, 0}, {0, -1, 0}}, {0, kInfinity}).has_value());
}

// Long lists nest in log2 of their length: a union of 40 spheres is 6 levels deep, not 39
// (beyond kMaxCsgDepth), and every sphere is in it once.
TEST(YamlPlacement, LongCsgListsFoldIntoABalancedTree) {
    std::string text = "objects:\n  - type: union\n    objects:\n";
    for (int i = 0; i < 40; ++i) {
        text += "      - {type: sphere, center: [" + std::to_string(i) + ", 0, 0], radius: 0.4}\n";
    }
    const Scene scene = parse(text);
    EXPECT_EQ(csg_depth(scene.objects[0].shape), 6);
    std::vector<float> centres;
    const auto collect = [&](const auto& self, const Shape& shape) -> void {
        if (const auto* csg = std::get_if<Csg>(&shape)) {
            EXPECT_EQ(csg->operation, CsgOperation::union_of);
            self(self, *csg->a);
            self(self, *csg->b);
        } else {
            centres.push_back(std::get<Sphere>(shape).center.x);
        }
    };
    collect(collect, scene.objects[0].shape);
    ASSERT_EQ(centres.size(), 40u);
    for (int i = 0; i < 40; ++i) EXPECT_EQ(centres[std::size_t(i)], float(i));  // in order
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
    expect_near(c.world_from_object()(Point3{0, 1, 0}), {0, 2, 3});
}

}  // namespace glint::yaml_placement_test
