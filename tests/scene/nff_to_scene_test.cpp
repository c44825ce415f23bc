// NFF to Scene: what the conversion makes of the format's conventions that the parser keeps, here
// the inside-only spheres and cones of negative radii, and materials the file repeats.
#include "glint/scene/nff/nff_to_scene.h"

#include <gtest/gtest.h>

#include <string>
#include <variant>

#include "glint/scene/nff/nff_parser.h"

namespace glint::nff_to_scene_test {
namespace {

const char* const kView =
    "v\nfrom 0 0 -8\nat 0 0 0\nup 0 1 0\nangle 25\nhither 0.001\nresolution 64 64\n"
    "f 1 0.5 0.5 0.7 0.3 10 0 0\n";

TEST(NffToScene, NegativeRadiiGiveInsideOnlyShapesDrawnTwoSidedWithAWarning) {
    // Lines 9 to 12: an inside-only sphere, an ordinary one, inside-only cones (both radii
    // negative; one negative beside a point).
    const NffScene nff = parse_nff(std::string(kView) +
                                       "s 0 0 0 -2.5\ns 1 0 0 1\nc 0 0 0 -1 0 1 0 -1\n"
                                       "c 0 0 0 -1 0 1 0 0\n",
                                   "neg.nff");
    const auto& inside = std::get<NffSphere>(nff.objects[0].primitive);
    EXPECT_TRUE(inside.inside_only);
    EXPECT_EQ(inside.radius, 2.5f);
    EXPECT_FALSE(std::get<NffSphere>(nff.objects[1].primitive).inside_only);
    const auto& cone = std::get<NffCone>(nff.objects[3].primitive);
    EXPECT_TRUE(cone.inside_only);
    EXPECT_EQ(cone.base_radius, 1);
    EXPECT_EQ(cone.apex_radius, 0);

    const Scene scene = nff_to_scene(nff);
    ASSERT_EQ(scene.objects.size(), 4u);
    EXPECT_EQ(std::get<Sphere>(scene.objects[0].shape).radius, 2.5f);
    EXPECT_EQ(std::get<Cylinder>(scene.objects[2].shape).radius, 1);
    ASSERT_EQ(scene.warnings.size(), 1u);
    EXPECT_EQ(scene.warnings[0],
              "neg.nff:9:1: 1 sphere and 2 cones with negative radii, which NFF makes visible "
              "from inside only, are drawn from both sides with the absolute radii (glint's "
              "surfaces are two-sided); the first is here");

    const Scene one = nff_to_scene(parse_nff(std::string(kView) + "s 0 0 0 -2.5\n", "one.nff"));
    ASSERT_EQ(one.warnings.size(), 1u);
    EXPECT_EQ(one.warnings[0],
              "one.nff:9:1: a sphere with a negative radius, which NFF makes visible from inside "
              "only, is drawn from both sides with the absolute radius (glint's surfaces are "
              "two-sided)");
    EXPECT_TRUE(
        nff_to_scene(parse_nff(std::string(kView) + "s 0 0 0 1\n", "a.nff")).warnings.empty());
}

TEST(NffToScene, RepeatedMaterialsBecomeOne) {
    // f1 and f3 are equal, f2 differs in its Ks; the triangles go into one mesh per material.
    const NffScene nff = parse_nff(std::string(kView) +
                                       "s 0 0 0 1\n"
                                       "f 1 0.5 0.5 0.7 0.4 10 0 0\ns 2 0 0 1\n"
                                       "f 1 0.5 0.5 0.7 0.3 10 0 0\ns 4 0 0 1\n"
                                       "p 3 0 0 0 1 0 0 0 1 0\n",
                                   "repeat.nff");
    ASSERT_EQ(nff.materials.size(), 3u);
    const Scene scene = nff_to_scene(nff);
    ASSERT_EQ(scene.materials.size(), 2u);
    EXPECT_EQ(scene.materials[0].name, "f1");
    EXPECT_EQ(scene.materials[1].name, "f2");
    EXPECT_EQ(scene.materials[1].reflect, 0.4f);
    ASSERT_EQ(scene.objects.size(), 4u);
    EXPECT_EQ(scene.objects[0].material, 0u);
    EXPECT_EQ(scene.objects[1].material, 1u);
    EXPECT_EQ(scene.objects[2].material, 0u);
    EXPECT_TRUE(std::holds_alternative<TriangleMesh>(scene.objects[3].shape));
    EXPECT_EQ(scene.objects[3].material, 0u);
}

}  // namespace
}  // namespace glint::nff_to_scene_test
