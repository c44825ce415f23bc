// summarize_scene(): objects by shape, triangles through instances, lights by kind, bounds.
#include "glint/scene/scene_summary.h"

#include <gtest/gtest.h>

#include "glint/scene/yaml/yaml_scene_loader.h"

namespace glint {
namespace {

TEST(SceneSummary, CountsObjectsTrianglesLightsAndBounds) {
    const Scene scene = parse_yaml_scene(
        "camera: {from: [0, 1, -5], at: [0, 0, 0]}\n"
        "lights:\n"
        "  - {type: point, position: [0, 5, 0]}\n"
        "  - {type: directional, direction: [0, -1, 0]}\n"
        "  - {type: rectangle, center: [0, 4, 0], u: [1, 0, 0], v: [0, 0, 1]}\n"
        "materials: {lamp: {emission: 1}, unused: {kd: 0.2}}\n"
        "objects:\n"
        "  - {type: sphere, center: [0, 0, 0], radius: 1, material: lamp}\n"
        "  - {type: sphere, center: [3, 0, 0], radius: 0.5}\n"
        "  - {type: triangle, vertices: [[0, 0, 5], [1, 0, 5], [0, 2, 5]]}\n"
        "  - {type: plane, point: [0, -1, 0], normal: [0, 1, 0]}\n",
        "summary.yaml");
    const SceneSummary s = summarize_scene(scene);
    // The rectangle light's visible face is an object too (the first), glowing but not counted
    // as an emitting object: its light is the rectangle's.
    EXPECT_EQ(s.objects, 5u);
    EXPECT_EQ(s.objects_by_shape.at("sphere"), 2u);
    EXPECT_EQ(s.objects_by_shape.at("triangle"), 1u);
    EXPECT_EQ(s.objects_by_shape.at("plane"), 1u);
    EXPECT_EQ(s.triangles, 1u);
    EXPECT_EQ(s.point_lights, 1u);
    EXPECT_EQ(s.directional_lights, 1u);
    EXPECT_EQ(s.area_lights, 1u);
    EXPECT_EQ(s.spot_lights, 0u);
    EXPECT_EQ(s.emitting_objects, 1u);
    EXPECT_EQ(s.unbounded_objects, 1u);
    // The face's glow, lamp, unused, and the default of the two objects without one.
    EXPECT_EQ(s.materials, 4u);
    EXPECT_EQ(s.bounds.min, (Point3{-1, -1, -1}));
    EXPECT_EQ(s.bounds.max, (Point3{3.5f, 4, 5}));  // the face at y = 4
}

TEST(SceneSummary, AnInstancedMeshCountsItsTrianglesOncePerPlacement) {
    const Scene scene = parse_yaml_scene(
        "camera: {from: [0, 1, -5], at: [0, 0, 0]}\n"
        "define:\n"
        "  tri: {type: triangle, vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}\n"
        "objects:\n"
        "  - {type: instance, of: tri}\n"
        "  - {type: instance, of: tri, transform: [{translate: [3, 0, 0]}]}\n",
        "instances.yaml");
    EXPECT_EQ(summarize_scene(scene).triangles, 2u);
}

}  // namespace
}  // namespace glint
