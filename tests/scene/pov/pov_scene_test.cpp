// POV-Ray scenes mapped onto glint's Scene: the camera (POV-Ray's left-handed one, its angle
// and default), lights, background and global settings, objects with transforms, CSG and
// declared objects, finishes as Phong materials, and located errors for what is not read.
#include "glint/scene/pov/pov_scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <numbers>

#include "glint/image/srgb.h"
#include "glint/sampling/perlin_noise.h"
#include "glint/scene/scene_error.h"

namespace glint::pov_scene_test {
namespace {

Scene parse(const std::string& text) {
    const ReadSandbox sandbox = make_read_sandbox("scene.pov");
    return parse_pov_scene(text, "scene.pov", sandbox);
}

std::string error_of(const std::string& text) {
    try {
        parse(text);
    } catch (const SceneError& e) {
        return format_scene_error(e);
    }
    return "";
}

double degrees(double radians) { return radians * 180 / std::numbers::pi; }

TEST(PovScene, TheDefaultCameraIsPovRaysAndLeftHanded) {
    const Scene s = parse("sphere { <0, 0, 5>, 1 }");
    EXPECT_TRUE(s.camera.left_handed);
    EXPECT_EQ(s.camera.from, (Point3{0, 0, 0}));
    EXPECT_EQ(s.camera.at, (Point3{0, 0, 1}));
    // up 1 over direction 1: 2 atan(1/2) vertically.
    EXPECT_NEAR(s.camera.fov, degrees(2 * std::atan(0.5)), 1e-4);
    EXPECT_FLOAT_EQ(s.camera.aspect, 1.33f);
    EXPECT_EQ(s.objects.size(), 1u);
}

// The right vector's length against up's is the view's shape, stretched over any image;
// image_width / image_height's is the image's own shape at any size.
TEST(PovScene, RightAndUpGiveTheViewItsShape) {
    EXPECT_FLOAT_EQ(parse("camera { location -130*z direction 8*z right 0.8*x }").camera.aspect,
                    0.8f);
    EXPECT_FLOAT_EQ(parse("camera { up 2*y right 3*x look_at z }").camera.aspect, 1.5f);
    EXPECT_FLOAT_EQ(parse("camera { orthographic up 2*y right 1*x }").camera.aspect, 0.5f);
    EXPECT_EQ(parse("camera { right x*image_width/image_height look_at z }").camera.aspect, 0);
    EXPECT_FLOAT_EQ(parse("camera { right -1.33*x up y }").camera.aspect, 1.33f);
}

TEST(PovScene, AngleIsHorizontalAndLookAtTurnsTheView) {
    const Scene s = parse("camera { location <0, 0, -10> look_at <0, 0, 0> angle 90 }");
    // right 1.33 gives a direction of 0.665 for 90 degrees across; up 1 over it vertically.
    EXPECT_NEAR(s.camera.fov, degrees(2 * std::atan(0.5 / 0.665)), 1e-3);
    EXPECT_EQ(s.camera.from, (Point3{0, 0, -10}));
    EXPECT_NEAR(s.camera.at.z, -10 + 0.665, 1e-5);
    // A right-handed right vector makes a right-handed camera.
    EXPECT_FALSE(parse("camera { right -1.33*x look_at z }").camera.left_handed);
    // So does up along the direction (right . up x direction = 0), as in POV-Ray's prism3
    // scenes: up z with the default direction z.
    EXPECT_FALSE(parse("camera { location <-10, 10, -10> up z look_at 0 }").camera.left_handed);
}

// shadowless: the light casts no shadows, whatever its kind.
TEST(PovScene, ShadowlessLightsCastNoShadows) {
    const Scene s = parse(R"(
        light_source { <0, 9, 0> color 1 shadowless }
        light_source { <0, 9, 0> color 1 parallel point_at 0 shadowless }
        light_source { <0, 9, 0> color 1 area_light x, z, 2, 2 shadowless }
        light_source { <0, 9, 0> color 1 })");
    ASSERT_EQ(s.lights.size(), 4u);
    EXPECT_FALSE(casts_shadows(s.lights[0]));
    EXPECT_FALSE(casts_shadows(s.lights[1]));
    EXPECT_FALSE(casts_shadows(s.lights[2]));
    EXPECT_TRUE(casts_shadows(s.lights[3]));
    EXPECT_TRUE(s.warnings.empty());
}

TEST(PovScene, LightsBackgroundAndGlobalSettings) {
    const Scene s = parse(R"(
        #version 3.7;
        light_source { <1, 2, 3> color rgb <1, 0.5, 0.25> }
        light_source { <0, 10, 0> color 1 spotlight point_at <0, 0, 0> radius 10 falloff 20 }
        light_source { <0, 10, 0> color 1 parallel point_at <0, 0, 0> }
        light_source { <0, 5, 0> color 1 area_light <2, 0, 0>, <0, 0, 2>, 3, 4 fade_distance 2 fade_power 2 }
        background { color rgb <0.1, 0.2, 0.3> }
        global_settings { ambient_light rgb 0.5 max_trace_level 7 adc_bailout 0.01 })");
    ASSERT_EQ(s.lights.size(), 4u);
    const auto& point = std::get<PointLight>(s.lights[0]);
    EXPECT_EQ(point.position, (Point3{1, 2, 3}));
    EXPECT_EQ(point.color, (Color{1, 0.5f, 0.25f}));
    const auto& spot = std::get<SpotLight>(s.lights[1]);
    EXPECT_EQ(spot.direction, (Vector3{0, -1, 0}));
    EXPECT_NEAR(spot.cos_cone, std::cos(20 * std::numbers::pi / 180), 1e-6);
    EXPECT_NEAR(spot.cos_falloff, std::cos(10 * std::numbers::pi / 180), 1e-6);
    EXPECT_EQ(std::get<DirectionalLight>(s.lights[2]).direction, (Vector3{0, -1, 0}));
    const auto& area = std::get<AreaLight>(s.lights[3]);
    EXPECT_EQ(area.shadow_rays, 12);
    // 2 / (1 + (d/2)^2) = 1 / (0.5 + d^2/8).
    EXPECT_EQ(area.attenuation.constant, 0.5f);
    EXPECT_EQ(area.attenuation.quadratic, 0.125f);
    EXPECT_EQ(s.settings.integrator, IntegratorKind::distributed);  // for the area light's penumbra
    EXPECT_EQ(s.settings.background, (Color{0.1f, 0.2f, 0.3f}));
    EXPECT_EQ(s.ambient, (Color{0.5f, 0.5f, 0.5f}));
    EXPECT_EQ(s.settings.max_depth, 7);
    EXPECT_EQ(s.settings.min_weight, 0.01f);
    EXPECT_TRUE(s.settings.transparent_shadows);  // POV-Ray's shadows pass transparent objects
}

TEST(PovScene, FinishesBecomePhongMaterials) {
    const Scene s = parse(R"(
        sphere { 0, 1 }
        sphere { 0, 1 pigment { rgbt <1, 0, 0, 0.6> }
                 finish { ambient 0.2 diffuse 0.7 phong 0.5 phong_size 30 reflection 0.25 }
                 interior { ior 1.5 } }
        sphere { 0, 1 finish { specular 0.4 roughness 0.02 } }
        sphere { 0, 1 finish { reflection { 0.1 0.8 metallic } } }
        sphere { 0, 1 finish { reflection { 0.2, 0.6 fresnel } diffuse 0.7, 0.2 } })");
    ASSERT_EQ(s.materials.size(), 5u);
    const Material& plain = s.materials[0];  // POV-Ray's defaults: black, ambient 0.1, diffuse 0.6
    EXPECT_EQ(std::get<Color>(plain.color), (Color{0, 0, 0}));
    EXPECT_FLOAT_EQ(plain.ka, 0.1f);
    EXPECT_FLOAT_EQ(plain.kd, 0.6f);
    EXPECT_EQ(plain.ks, 0);
    const Material& glass = s.materials[1];
    EXPECT_EQ(std::get<Color>(glass.color), (Color{1, 0, 0}));
    // Ambient and diffuse scaled by the pigment's opacity, 1 - 0.6, as POV-Ray scales them.
    EXPECT_FLOAT_EQ(glass.ka, 0.2f * 0.4f);
    EXPECT_FLOAT_EQ(glass.kd, 0.7f * 0.4f);
    EXPECT_EQ(glass.highlight, Highlight::phong);
    EXPECT_FLOAT_EQ(glass.ks, 0.5f);
    EXPECT_FLOAT_EQ(glass.shininess, 30);
    EXPECT_FLOAT_EQ(glass.reflect, 0.25f);
    EXPECT_FLOAT_EQ(glass.transmit, 0.6f);
    EXPECT_FLOAT_EQ(glass.ior, 1.5f);
    // reflection { min max }, with or without a comma: the maximum.
    EXPECT_FLOAT_EQ(s.materials[3].reflect, 0.8f);
    EXPECT_FLOAT_EQ(s.materials[4].reflect, 0.6f);
    EXPECT_FLOAT_EQ(s.materials[4].kd, 0.7f);  // the light from behind is read past
    ASSERT_EQ(s.warnings.size(), 1u);
    EXPECT_NE(s.warnings[0].find("diffuse light from behind"), std::string::npos);
    const Material& shiny = s.materials[2];
    EXPECT_EQ(shiny.highlight, Highlight::blinn);
    EXPECT_FLOAT_EQ(shiny.shininess, 50);  // 1 / roughness
}

TEST(PovScene, TransformsCsgAndDeclaredObjects) {
    const Scene s = parse(R"(
        #declare Ball = sphere { 0, 1 pigment { rgb 1 } }
        #declare Away = transform { translate <0, 0, 3> }
        object { Ball scale 2 transform { Away translate z * 2 inverse translate z * 10 } no_shadow }
        union { sphere { 0, 1 } box { -1, 1 } translate x }
        difference { box { -1, 1 } sphere { 0, 1.2 } sphere { y, 0.5 } })");
    ASSERT_EQ(s.objects.size(), 4u);  // the union's two objects each on their own
    const auto& placed = std::get<Transformed>(s.objects[0].shape);
    EXPECT_EQ(placed.world_from_object()(Point3{1, 0, 0}), (Point3{2, 0, 5}));
    EXPECT_FALSE(s.objects[0].casts_shadow);
    EXPECT_TRUE(std::holds_alternative<Transformed>(s.objects[1].shape));
    const auto& outer = std::get<Csg>(s.objects[3].shape);  // box - (sphere + sphere)
    EXPECT_EQ(outer.operation, CsgOperation::difference);
    EXPECT_TRUE(std::holds_alternative<Box>(*outer.a));
    EXPECT_EQ(std::get<Csg>(*outer.b).operation, CsgOperation::merge);
}

// What a difference takes away is one solid: where two of its parts overlap, a point inside
// one is inside what is taken, though the ray has left the other.
TEST(PovScene, ADifferenceTakesAwayOverlappingPartsWhole) {
    const Scene s = parse(R"(
        difference { box { -1, 1 } box { <-2, -2, -2>, <2, 0.5, 2> } box { <-3, 0, -3>, 3 } })");
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_FALSE(intersect(s.objects[0].shape, Ray{{0, 0.25f, -5}, {0, 0, 1}}, {0, kInfinity}));
    EXPECT_FALSE(intersect(s.objects[0].shape, Ray{{0, -0.5f, -5}, {0, 0, 1}}, {0, kInfinity}));
}

// trace() meets a declared object as POV-Ray 3.7 does (its #debug output for the same lines):
// the first hit and the outward normal, from outside and from inside, and <0, 0, 0> for a miss
// and for what a difference cut away.
TEST(PovScene, TraceFindsTheFirstHitAndItsNormal) {
    const Scene s = parse(R"(
        #declare N = <0, 0, 0>; #declare M = <0, 0, 0>; #declare K = <0, 0, 0>;
        #declare L = <0, 0, 0>;
        #declare Ball = sphere { 0, 1 scale 2 translate x }
        #declare P = trace(Ball, <1, 5, 0>, -y, N);
        #debug concat("P ", vstr(3, P, ",", 0, 4), " N ", vstr(3, N, ",", 0, 4))
        #declare Q = trace(Ball, <10, 5, 0>, -y, M);
        #debug concat("Q ", vstr(3, Q, ",", 0, 4), " M ", vstr(3, M, ",", 0, 4))
        #declare Box = box { -1, 1 }
        #declare R = trace(Box, <0, 0, 0>, x, K);
        #debug concat("R ", vstr(3, R, ",", 0, 4), " K ", vstr(3, K, ",", 0, 4))
        #declare S = trace(Box, <0, 0.5, -5>, z);
        #debug concat("S ", vstr(3, S, ",", 0, 4))
        #declare Hole = difference { box { -1, 1 } sphere { 0, 1.2 } }
        #declare T = trace(Hole, <0, 0, -5>, z, L);
        #debug concat("T ", vstr(3, T, ",", 0, 4), " L ", vstr(3, L, ",", 0, 4))
        sphere { P, 0.1 })");
    const std::vector<std::string> expected = {
        "#debug: P 1.0000,2.0000,0.0000 N 0.0000,1.0000,0.0000",
        "#debug: Q 0.0000,0.0000,0.0000 M 0.0000,0.0000,0.0000",
        "#debug: R 1.0000,0.0000,0.0000 K 1.0000,0.0000,0.0000", "#debug: S 0.0000,0.5000,-1.0000",
        "#debug: T 0.0000,0.0000,0.0000 L 0.0000,0.0000,0.0000"};
    EXPECT_EQ(s.warnings, expected);
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_TRUE(intersect(s.objects[0].shape, Ray{{1, 2, -5}, {0, 0, 1}}, {0, kInfinity}));
}

TEST(PovScene, TraceRefusesWhatItCannotTake) {
    EXPECT_NE(error_of("#declare P = trace(1, 0, y);")
                  .find("trace takes an object first, got a "
                        "float"),
              std::string::npos);
    EXPECT_NE(error_of("#declare B = box { -1, 1 } #declare P = trace(B, 0, y, Undeclared);")
                  .find("1:56: error: trace's fourth argument must be a vector declared before"),
              std::string::npos);
    EXPECT_NE(error_of("#declare B = box { -1, 1 } #declare P = trace(B, 0, 0);")
                  .find("trace's direction is zero or beyond a float's range"),
              std::string::npos);
}

// Long CSGs (a polyhedron is an intersection of its faces' planes) become balanced trees: each
// level of glint's CSG walks its operands' hits again, so depth, not count, sets the cost.
TEST(PovScene, LongCsgsAreBalancedTrees) {
    const Scene s = parse(R"(
        intersection { #for (I, 0, 11) plane { x, 1 rotate <I * 30, I * 45, 0> } #end
                       sphere { 0, 2 } })");
    ASSERT_EQ(s.objects.size(), 1u);
    const std::function<int(const Shape&)> depth = [&](const Shape& shape) {
        const auto* csg = std::get_if<Csg>(&shape);
        return csg ? 1 + std::max(depth(*csg->a), depth(*csg->b)) : 0;
    };
    EXPECT_EQ(depth(s.objects[0].shape), 4);  // 13 operands: ceil(log2 13)
}

TEST(PovScene, SmoothTrianglesCarryTheirNormals) {
    const Scene s = parse(R"(
        mesh { smooth_triangle { <0, 0, 0>, <0, 0, -1>, <1, 0, 0>, <1, 0, -1>, <0, 1, 0>, <0, 1, -1> }
               triangle { <0, 0, 1>, <1, 0, 1>, <0, 1, 1> } }
        smooth_triangle { 0, y, x, y, z, y })");
    ASSERT_EQ(s.objects.size(), 2u);
    const MeshData& mesh = *std::get<TriangleMesh>(s.objects[0].shape).data;
    ASSERT_EQ(mesh.normals.size(), 6u);
    EXPECT_NEAR(mesh.normals[1].x, 1 / std::sqrt(2.0f), 1e-6);  // normalised as given
    EXPECT_EQ(mesh.normals[3], (Normal3{0, 0, 1}));             // the flat one's face
    EXPECT_EQ(std::get<TriangleMesh>(s.objects[1].shape).data->normals.size(), 3u);
}

TEST(PovScene, RotateIsAboutXThenYThenZ) {
    const Scene s = parse("sphere { 0, 1 rotate <90, 0, 90> }");
    const auto& t = std::get<Transformed>(s.objects[0].shape);
    // y turns to z about x, then x turns to y about z: y ends at z.
    const Point3 p = t.world_from_object()(Point3{0, 1, 0});
    EXPECT_NEAR(p.x, 0, 1e-6);
    EXPECT_NEAR(p.y, 0, 1e-6);
    EXPECT_NEAR(p.z, 1, 1e-6);
}

TEST(PovScene, WhatIsNotReadIsALocatedErrorNamingIt) {
    EXPECT_EQ(error_of("sphere { 0, 1\n  split_union on }"),
              "scene.pov:2:3: error: \"split_union\" is not supported as an object modifier yet\n"
              "    2 |   split_union on }\n"
              "      |   ^~~~~~~~~~~\n"
              "note: docs/povray.md lists what glint reads\n");
    EXPECT_NE(error_of("isosurface { }").find("an isosurface needs a function { }"),
              std::string::npos);
    EXPECT_NE(error_of("sphere { 0, -1 }").find("sphere radius must be > 0"), std::string::npos);
    EXPECT_NE(error_of("sphere { 0, 1 pigment { julia <0.3, 0.4> 20 } }")
                  .find("pigment pattern \"julia\" is not supported yet"),
              std::string::npos);
}

// normal { }: POV-Ray's own patterns and any pigment pattern's slope, with the amount after the
// pattern or as bump_size, declared and modified, placed as the object is.
TEST(PovScene, NormalsTiltByTheirPatternPlacedWithTheObject) {
    const Scene s = parse(R"(
        #declare Bumpy = normal { bumps 0.3 scale 0.5 }
        sphere { 0, 1 normal { Bumpy bump_size 0.7 } translate x * 4 }
        sphere { 0, 1 texture { normal { ripples frequency 3 } } }
        box { 0, 1 normal { gradient y, 0.25 accuracy 0.01 turbulence 0.2 } }
        sphere { 0, 1 normal { agate } normal { wrinkles } })");
    ASSERT_EQ(s.objects.size(), 4u);
    const auto pattern_of = [&](std::size_t i) -> const NormalPattern& {
        const Material& m = s.materials[s.objects[i].material];
        EXPECT_TRUE(m.maps && m.maps->normal_pattern);
        return *m.maps->normal_pattern;
    };
    const NormalPattern& bumpy = pattern_of(0);
    EXPECT_EQ(bumpy.kind, NormalPatternKind::bumps);
    EXPECT_FLOAT_EQ(bumpy.amount, 0.7f);
    const Point3 p = bumpy.to_pattern(Point3{5, 1, 0});  // scaled by 0.5, then moved by 4
    EXPECT_NEAR(p.x, 2, 1e-5);
    EXPECT_NEAR(p.y, 2, 1e-5);
    EXPECT_EQ(pattern_of(1).kind, NormalPatternKind::ripples);
    EXPECT_FLOAT_EQ(pattern_of(1).amount, 0.5f);  // POV-Ray's default
    EXPECT_FLOAT_EQ(pattern_of(1).pattern.frequency, 3);
    const NormalPattern& ramp = pattern_of(2);
    EXPECT_EQ(ramp.kind, NormalPatternKind::slope);
    EXPECT_EQ(ramp.pattern.kind, PatternKind::gradient);
    EXPECT_EQ(ramp.pattern.direction, (Vector3{0, 1, 0}));
    EXPECT_FLOAT_EQ(ramp.amount, 0.25f);
    EXPECT_FLOAT_EQ(ramp.accuracy, 0.01f);
    EXPECT_FLOAT_EQ(ramp.pattern.turbulence.x, 0.2f);
    EXPECT_EQ(pattern_of(3).kind, NormalPatternKind::wrinkles);  // the later normal
    EXPECT_TRUE(s.warnings.empty());
    EXPECT_NE(error_of("sphere { 0, 1 normal { bumps accuracy 0 } }")
                  .find("scene.pov:1:39: error: accuracy must be > 0"),
              std::string::npos);
    EXPECT_NE(error_of("sphere { 0, 1 normal { bumps color_map { [0 rgb 0] } sheen 2 } }")
                  .find("\"sheen\" is not supported in a normal yet"),
              std::string::npos);
}

// pigment_pattern: the slope of a pigment's grey, the pigment placed in the normal's space; one
// glint does not read stops the scene.
TEST(PovScene, PigmentPatternNormalsTiltByThePigmentsGrey) {
    const Scene s = parse(
        "sphere { 0, 1 normal { pigment_pattern { gradient x color_map { [0 rgb 0] [1 rgb 1] } "
        "scale 2 }, 0.6 } }");
    ASSERT_EQ(s.objects.size(), 1u);
    const Material& m = s.materials[s.objects[0].material];
    ASSERT_TRUE(m.maps && m.maps->normal_pattern);
    const NormalPattern& np = *m.maps->normal_pattern;
    EXPECT_EQ(np.kind, NormalPatternKind::slope);
    EXPECT_FLOAT_EQ(np.amount, 0.6f);
    ASSERT_TRUE(np.pigment);
    SurfacePoint sp;
    sp.p = {1, 0, 0};  // half way up the ramp scaled by 2
    EXPECT_NEAR(evaluate(*np.pigment, sp).g, 0.5f, 1e-5f);
    EXPECT_TRUE(s.warnings.empty());
    EXPECT_NE(error_of("sphere { 0, 1 normal { pigment_pattern { julia <0, 1> 9 } } }")
                  .find("pigment pattern \"julia\" is not supported yet"),
              std::string::npos);
}

// A normal for each part of a list pattern is not read yet: the surface stays smooth, and says so.
TEST(PovScene, ListPatternsOfNormalsLeaveTheSurfaceSmooth) {
    const Scene s =
        parse("sphere { 0, 1 normal { checker normal { bumps } normal { dents 0.3 } scale 2 } }");
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_FALSE(s.materials[s.objects[0].material].maps);
    ASSERT_EQ(s.warnings.size(), 1u);
    EXPECT_NE(s.warnings[0].find("\"checker of normals\" is not supported yet"), std::string::npos);
}

// As an include file declares what a scene may never use: only what is used stops the scene.
TEST(PovScene, UnreadDeclarationsStopOnlyTheObjectsThatUseThem) {
    const Scene s = parse(R"(
        #declare Fractal = pigment { julia <0.3, 0.4> 20 color_map { [0 rgb 0] [1 rgb 1] } }
        #declare Map = color_map { [0 rgb 0] [1 rgb 1] }
        #declare Quilts = normal { quilted 0.5 control0 1 }
        sphere { 0, 1 pigment { rgb 1 } normal { Quilts } })");
    EXPECT_EQ(s.objects.size(), 1u);
    ASSERT_EQ(s.warnings.size(), 1u);
    EXPECT_EQ(s.warnings[0],
              "normal pattern \"quilted\" is not supported yet: surfaces with it stay smooth");
    EXPECT_NE(
        error_of(
            "#declare Cloudy = pigment { julia <0.3, 0.4> 9 }\nsphere { 0, 1 pigment { Cloudy } }")
            .find("scene.pov:1:29: error: pigment pattern \"julia\" is not supported yet"),
        std::string::npos);
}

TEST(PovScene, DeprecatedDeclarationsAndMetallicAmounts) {
    const Scene s = parse(R"(
        #declare M = 0.5;
        #declare deprecated once "use T_New" T_Old = texture { finish { metallic M brilliance 2 } }
        sphere { 0, 1 texture { T_Old } })");
    EXPECT_EQ(s.objects.size(), 1u);
}

// Textures made and dropped one after another must never share a material.
TEST(PovScene, EachObjectsOwnTextureIsItsOwnMaterial) {
    const Scene s = parse(
        "#version 3.7; #for (I, 1, 50) sphere { x * I, 0.5 pigment { rgb <I / 50, 0, 0> } } #end");
    ASSERT_EQ(s.objects.size(), 50u);
    for (std::size_t i = 0; i < 50; ++i)
        EXPECT_FLOAT_EQ(std::get<Color>(s.materials[s.objects[i].material].color).r,
                        float(i + 1) / 50);
}

// Colours stay as written, and the image is decoded from the space of the assumed_gamma, as
// POV-Ray takes its results; one older than POV-Ray 3.7 without one is not corrected at all (its
// results are the file's values: sRGB's), a 3.7 one is linear.
TEST(PovScene, TheAssumedGammaIsTheWorkingSpaceOfTheColours) {
    using Transfer = WorkingSpace::Transfer;
    const auto space = [](const std::string& text) {
        const Scene s = parse(text + " sphere { 0, 1 pigment { rgb <0.5, 0, 0> } }");
        EXPECT_FLOAT_EQ(std::get<Color>(s.materials[s.objects[0].material].color).r, 0.5f);
        return s.settings.working_space;
    };
    EXPECT_EQ(space("#version 3.7;").transfer, Transfer::linear);
    const WorkingSpace two = space("#version 3.7; global_settings { assumed_gamma 2 }");
    EXPECT_EQ(two.transfer, Transfer::gamma);
    EXPECT_FLOAT_EQ(two.gamma, 2);
    EXPECT_EQ(space("").transfer, Transfer::srgb);
    EXPECT_EQ(space("#version 3.6;").transfer, Transfer::srgb);
    EXPECT_EQ(space("global_settings { assumed_gamma 1.0 }").transfer, Transfer::linear);
    const Scene lit = parse("light_source { 0 rgb 0.5 } background { rgb 0.5 }");
    EXPECT_FLOAT_EQ(std::get<PointLight>(lit.lights[0]).color.g, 0.5f);
    EXPECT_FLOAT_EQ(lit.settings.background.b, 0.5f);
    EXPECT_EQ(error_of("global_settings { assumed_gamma 0 }"),
              "scene.pov:1:33: error: assumed_gamma must be in (0, 10]\n"
              "    1 | global_settings { assumed_gamma 0 }\n"
              "      |                                 ^\n");
}

// A camera looking straight down its sky keeps its right vector as given, as POV-Ray does.
TEST(PovScene, ACameraLookingAlongItsSkyKeepsItsRight) {
    const Scene s = parse("camera { location 6 * y look_at 0 }");
    const CameraSpec& c = s.camera;
    EXPECT_NEAR(c.at.y - c.from.y, -1, 1e-6);
    EXPECT_NEAR(std::abs(c.up.z), 1, 1e-6);  // across the view and the right vector, x
    EXPECT_NEAR(c.up.x, 0, 1e-6);
    ASSERT_EQ(s.warnings.size(), 1u);
    EXPECT_NE(s.warnings[0].find("looks along its sky"), std::string::npos);
    EXPECT_NE(error_of("camera { location 6 * y look_at 0 right y }")
                  .find("camera sky and right are both parallel to its view"),
              std::string::npos);
}

TEST(PovScene, CamerasAndLightsCanBeDeclaredAndPlacedAsObjects) {
    const Scene s = parse(R"(
        #version 3.7;
        #declare Cam = camera { location <0, 0, -5> look_at 0 }
        #declare Lamp = light_source { <0, 0, 0> color rgb 1 }
        camera { Cam translate <1, 0, 0> }
        object { Lamp translate <0, 4, 0> }
        light_source { Lamp translate <0, 0, 2> }
        union {
            light_source { <1, 0, 0> rgb 1 looks_like { sphere { 0, 0.1 } } }
            sphere { 0, 1 }
            translate <0, 0, 3>
        }
        difference { box { -1, 1 } sphere { 0, 1.2 } light_source { <0, 2, 0> rgb 1 } })");
    EXPECT_EQ(s.camera.from, (Point3{1, 0, -5}));
    EXPECT_EQ(s.camera.at, (Point3{1, 0, -4}));
    ASSERT_EQ(s.lights.size(), 4u);
    EXPECT_EQ(std::get<PointLight>(s.lights[0]).position, (Point3{0, 4, 0}));
    EXPECT_EQ(std::get<PointLight>(s.lights[1]).position, (Point3{0, 0, 2}));
    EXPECT_EQ(std::get<PointLight>(s.lights[2]).position, (Point3{1, 0, 3}));
    EXPECT_EQ(std::get<PointLight>(s.lights[3]).position, (Point3{0, 2, 0}));
    // The looks_like sphere at the light casts no shadow; the union's sphere and the CSG.
    ASSERT_EQ(s.objects.size(), 3u);
    EXPECT_FALSE(s.objects[0].casts_shadow);
    EXPECT_TRUE(std::holds_alternative<Csg>(s.objects[2].shape));
}

// POV-Ray's matrix: rows a point multiplies from the left, the last one the translation.
TEST(PovScene, MatrixShearsAndMoves) {
    const Scene s = parse("sphere { 0, 1 matrix <1, 0, 0,  0, 1, -0.5,  0, 0, 1,  1, 2, 3> }");
    const auto& placed = std::get<Transformed>(s.objects[0].shape);
    // (x, y, z) -> (x + 1, y + 2, z - 0.5 y + 3).
    EXPECT_EQ(placed.world_from_object()(Point3{0, 2, 0}), (Point3{1, 4, 2}));
    EXPECT_EQ(placed.world_from_object()(Point3{1, 0, 1}), (Point3{2, 2, 4}));
}

TEST(PovScene, CommasBetweenValuesMayBeLeftOut) {
    const Scene s = parse(R"(
        #version 3.7;
        box { <0, 0, 0> <1, 2, 3> }
        cylinder { <0, 0, 0> <0, 1, 0> 0.5 }
        object { sphere { <0, 0, 0> 1 } pigment { checker rgb 1 rgb 0 } })");
    ASSERT_EQ(s.objects.size(), 3u);
    EXPECT_EQ(std::get<Box>(s.objects[0].shape).max, (Point3{1, 2, 3}));
    const PatternTexture& checker =
        *std::get<PatternTexturePtr>(s.materials[s.objects[2].material].color);
    EXPECT_EQ(checker.spec.kind, PatternKind::checker);
    ASSERT_EQ(checker.colors.size(), 2u);
    EXPECT_EQ(checker.colors[0].color, (Color{1, 1, 1}));
    EXPECT_EQ(checker.colors[1].color, (Color{0, 0, 0}));
}

TEST(PovScene, PatternsReadTheirMapsWavesAndTurbulence) {
    const Scene s = parse(R"(
        #version 3.7;
        #declare Map = color_map { [0.5 rgb 1] [0 rgb 0] }
        sphere { 0, 1 pigment { gradient <0, 2, 0> color_map { Map } frequency 2 phase 0.5
                                turbulence 0.3 octaves 3 omega 0.4 lambda 3 sine_wave } }
        sphere { 0, 1 pigment { marble color_map { [0 0.5 color rgb 0 color rgb 1] } } }
        sphere { 0, 1 pigment { spotted } }
        sphere { 0, 1 pigment { bumps } })");
    ASSERT_EQ(s.objects.size(), 4u);
    const PatternTexture& gradient =
        *std::get<PatternTexturePtr>(s.materials[s.objects[0].material].color);
    EXPECT_EQ(gradient.spec.kind, PatternKind::gradient);
    EXPECT_EQ(gradient.spec.direction, (Vector3{0, 1, 0}));
    EXPECT_EQ(gradient.spec.frequency, 2);
    EXPECT_EQ(gradient.spec.phase, 0.5f);
    EXPECT_EQ(gradient.spec.turbulence, (Vector3{0.3f, 0.3f, 0.3f}));
    EXPECT_EQ(gradient.spec.octaves, 3);
    EXPECT_EQ(gradient.spec.omega, 0.4f);
    EXPECT_EQ(gradient.spec.lambda, 3);
    EXPECT_EQ(gradient.spec.wave, PatternWave::sine);
    // Entries written out of order are taken sorted.
    ASSERT_EQ(gradient.colors.size(), 2u);
    EXPECT_EQ(gradient.colors[0].at, 0);
    EXPECT_EQ(gradient.colors[1].color, (Color{1, 1, 1}));
    const PatternTexture& marble =
        *std::get<PatternTexturePtr>(s.materials[s.objects[1].material].color);
    EXPECT_EQ(marble.spec.wave, PatternWave::triangle);
    ASSERT_EQ(marble.colors.size(), 2u);  // the old form's two colours
    EXPECT_EQ(marble.colors[1].at, 0.5f);
    const PatternTexture& spotted =
        *std::get<PatternTexturePtr>(s.materials[s.objects[2].material].color);
    EXPECT_EQ(spotted.spec.kind, PatternKind::bozo);
    EXPECT_EQ(spotted.colors.back().color, (Color{1, 1, 1}));  // POV-Ray's default map
    EXPECT_EQ(std::get<PatternTexturePtr>(s.materials[s.objects[3].material].color)->spec.kind,
              PatternKind::bozo);  // bumps as a pigment
}

// A pattern lies where its object puts it: transforms after the pigment move it, and a union's
// texture lies in the union's frame for every child.
TEST(PovScene, PatternsArePlacedByTheirObjectsTransforms) {
    const Scene s = parse(R"(
        #version 3.7;
        sphere { 0, 1 pigment { gradient x scale 2 } translate <5, 0, 0> }
        union { sphere { 0, 1 } sphere { x, 1 } pigment { gradient x } translate <0, 3, 0> })");
    ASSERT_EQ(s.objects.size(), 3u);
    const PatternTexture& moved =
        *std::get<PatternTexturePtr>(s.materials[s.objects[0].material].color);
    EXPECT_EQ(moved.to_pattern(Point3{7, 0, 0}), (Point3{1, 0, 0}));
    // One material for both children: the same texture in the same frame.
    EXPECT_EQ(s.objects[1].material, s.objects[2].material);
    const PatternTexture& shared =
        *std::get<PatternTexturePtr>(s.materials[s.objects[1].material].color);
    EXPECT_EQ(shared.to_pattern(Point3{0.25f, 3, 0}), (Point3{0.25f, 0, 0}));
    EXPECT_NE(error_of("sphere { 0, 1 pigment { gradient 0 } }")
                  .find("gradient direction must not be zero"),
              std::string::npos);
    EXPECT_NE(error_of("#declare M = color_map { }").find("needs at least one [value colour]"),
              std::string::npos);
}

// A sky_sphere is baked into glint's sky image: its layers over the background, and emission.
TEST(PovScene, SkySpheresBecomeTheSkyImage) {
    const Scene s = parse(R"(
        #version 3.7;
        #declare Sky = sky_sphere { pigment { gradient y color_map { [0 rgb <1, 0, 0>] [1 rgb <0, 0, 1>] } } }
        background { rgb <0, 1, 0> }
        sky_sphere { Sky pigment { rgbt <1, 1, 1, 0.75> } emission 2 })");
    ASSERT_TRUE(s.sky.has_value());
    const Sky sky(*s.sky);
    // Straight up: blue, a quarter of it through the white layer, three quarters white, doubled.
    const Color up = sky.radiance({0, 1, 0});
    EXPECT_NEAR(up.r, 2 * 0.25, 0.01);
    EXPECT_NEAR(up.b, 2 * (0.25 + 0.75), 0.01);
    // Just above the horizon the gradient is y: mostly red below the layer.
    const float y = 0.2f / std::sqrt(1.04f);
    EXPECT_NEAR(sky.radiance({1, 0.2f, 0}).r, 2 * (0.25 + 0.75 * (1 - y)), 0.02);
    // A transparent sky shows the background.
    const Scene clear =
        parse("#version 3.7; background { rgb <0, 1, 0> } sky_sphere { pigment { rgbt 1 } }");
    EXPECT_NEAR(Sky(*clear.sky).radiance({0, 0, 1}).g, 1, 1e-4);
    EXPECT_NE(error_of("sky_sphere { sphere { 0, 1 } }")
                  .find("\"sphere\" is not supported in a sky_sphere yet"),
              std::string::npos);
}

// pigment_map: a pattern choosing between pigments, each placed inside the map's space; the
// same in a sky; average; a list pattern of pigments; and the errors.
TEST(PovScene, PigmentMapsChooseBetweenPigments) {
    const Scene s = parse(R"(
        #version 3.7;
        #declare Cells = pigment { checker rgb 0, rgb 1 scale 0.5 }
        sphere { 0, 1 pigment { gradient x pigment_map { [0 rgb <1, 0, 0>] [1 Cells] } scale 2 } }
        sphere { 0, 1 pigment { average pigment_map { [1 rgb <1, 0, 0>] [3 rgb <0, 0, 1>] } } }
        sphere { 0, 1 pigment { checker pigment { rgb <1, 1, 0> }, pigment { gradient y } } }
        sky_sphere { pigment { gradient y pigment_map { [0 rgb 0] [1 gradient x] } } })");
    ASSERT_EQ(s.objects.size(), 3u);
    const auto color_at = [&](std::size_t object, Point3 p) {
        SurfacePoint sp;
        sp.p = p;
        return evaluate(s.materials[s.objects[object].material].color, sp);
    };
    // At x = 1 the gradient is 1/2: half red, half the checker, whose cell (1, 0, 0) is white.
    const Color half = color_at(0, {1, 0.25f, 0.25f});
    EXPECT_FLOAT_EQ(half.r, 1);
    EXPECT_FLOAT_EQ(half.g, 0.5f);
    EXPECT_FLOAT_EQ(half.b, 0.5f);
    EXPECT_EQ(color_at(0, {0, 0.25f, 0.25f}), (Color{1, 0, 0}));
    const Color averaged = color_at(1, {0.3f, 0.6f, 0.9f});
    EXPECT_FLOAT_EQ(averaged.r, 0.25f);
    EXPECT_FLOAT_EQ(averaged.b, 0.75f);
    EXPECT_EQ(color_at(2, {0.5f, 0.5f, 0.5f}), (Color{1, 1, 0}));               // an even cell
    EXPECT_EQ(color_at(2, {1.5f, 0.25f, 0.5f}), (Color{0.25f, 0.25f, 0.25f}));  // gradient y
    // The sky: at height y, y of the way from black to the gradient x's value there.
    ASSERT_TRUE(s.sky.has_value());
    for (const Vector3 d : {Vector3{0.8f, 0.6f, 0}, normalize(Vector3{0.5f, 0.2f, 0.8f})})
        EXPECT_NEAR(Sky(*s.sky).radiance(d).r, d.y * d.x, 0.02);
    EXPECT_NE(error_of("sphere { 0, 1 pigment { average } }")
                  .find("scene.pov:1:25: error: average needs a pigment_map"),
              std::string::npos);
    EXPECT_NE(error_of("sphere { 0, 1 pigment { gradient x pigment_map { [0 rgb 1] [1 "
                       "julia <0, 1> 9] } } }")
                  .find("pigment pattern \"julia\" is not supported yet"),
              std::string::npos);
    EXPECT_NE(error_of("sky_sphere { pigment { julia <0, 1> 9 } }")
                  .find("scene.pov:1:24: error: pigment pattern \"julia\" is not supported yet"),
              std::string::npos);
    EXPECT_NE(error_of("sphere { 0, 1 pigment { gradient x pigment_map { [0 rgb 1 } } }")
                  .find("scene.pov:1:59: error: expected ']' after the pigment, got '}'"),
              std::string::npos);
}

// As POV-Ray: an orthographic camera without up or right, or with an angle, sees the area a
// perspective camera of the same vectors sees at look_at; with up or right, their size.
TEST(PovScene, OrthographicViewsAreSizedAsPovRaySizesThem) {
    // Default up 1 over direction 1, 10 away: 10 high.
    EXPECT_NEAR(parse("camera { orthographic location <0, 0, -10> look_at 0 }").camera.height, 10,
                1e-4);
    // angle 90 across right 1.33: direction 0.665, so 10 / 0.665 high.
    EXPECT_NEAR(
        parse("camera { orthographic location <0, 0, -10> look_at 0 angle 90 }").camera.height,
        10 / 0.665, 1e-3);
    // up given: its length.
    EXPECT_NEAR(parse("camera { orthographic location <0, 0, -10> look_at 0 up 3 * y right 4 * x }")
                    .camera.height,
                3, 1e-5);
    // angle without a number: the default direction's view, as without it.
    EXPECT_NEAR(
        parse("camera { orthographic location <0, 0, -4> look_at 0 up 3 * y angle }").camera.height,
        12, 1e-4);
}

// POV-Ray's wide cameras onto glint's projections: the angle is the field of view (90 unless
// given); a cylinder's kind picks its axis and whether it looks parallel along it, the extent
// along the axis being up's length (kinds 1, 3) or right's (2, 4).
TEST(PovScene, WideCamerasTakeTheirAngleAndACylindersKind) {
    const CameraSpec fisheye = parse("camera { fisheye location 0 look_at z angle 200 }").camera;
    EXPECT_EQ(fisheye.projection, Projection::fisheye);
    EXPECT_FLOAT_EQ(fisheye.fov, 200);
    EXPECT_FLOAT_EQ(parse("camera { ultra_wide_angle look_at z }").camera.fov, 90);
    EXPECT_EQ(parse("camera { panoramic look_at z }").camera.projection, Projection::panoramic);
    const CameraSpec three =
        parse("camera { cylinder 3 location 0 up 20 * y look_at z angle 200 }").camera;
    EXPECT_EQ(three.projection, Projection::cylindrical);
    EXPECT_TRUE(three.cylinder_parallel);
    EXPECT_FALSE(three.cylinder_axis_across);
    EXPECT_FLOAT_EQ(three.height, 20);
    const CameraSpec two = parse("camera { cylinder 2 right 2 * x look_at z }").camera;
    EXPECT_TRUE(two.cylinder_axis_across);
    EXPECT_FALSE(two.cylinder_parallel);
    EXPECT_FLOAT_EQ(two.height, 2);
    const CameraSpec spherical = parse("camera { spherical angle 180, 120 look_at z }").camera;
    EXPECT_FLOAT_EQ(spherical.fov, 180);
    EXPECT_FLOAT_EQ(spherical.vertical_fov, 120);
    EXPECT_FLOAT_EQ(parse("camera { spherical look_at z }").camera.vertical_fov, 180);
    // perspective after a wide type goes back to the pinhole.
    EXPECT_EQ(parse("camera { fisheye perspective look_at z }").camera.projection,
              Projection::perspective);
    EXPECT_NE(error_of("camera { fisheye angle 400 }")
                  .find("error: camera angle must be in (0, 360] for a fisheye camera"),
              std::string::npos);
    EXPECT_NE(error_of("camera { cylinder 5 }").find("error:"), std::string::npos);
    EXPECT_NE(
        error_of("camera { spherical angle 360, 200 }").find("vertical angle must be in (0, 180]"),
        std::string::npos);
}

// function { } as a pigment pattern: its value at the pattern's point, wrapped into [0, 1] as
// other patterns' values are; POV-Ray's floor, ceil, int, mod and div and the render's floats
// (image_width) written out. A function glint cannot compute stops only a scene that uses it.
TEST(PovScene, FunctionPatternsAreTheirFunctionsValue) {
    const Scene s = parse(R"(
        #declare F = function(a) { mod(a, 2) + ceil(a) - floor(a) + int(-a) + div(a, 2) }
        sphere { 0, 1 pigment { function { F(x) / image_width } color_map { [0 rgb 0] [1 rgb 1] } } }
        #declare Unused = pigment { function { select(x, 0, 1) } }
        sphere { 0, 1 pigment { function { x * 3 } } })");
    ASSERT_EQ(s.objects.size(), 2u);
    const PatternTexture& f =
        *std::get<PatternTexturePtr>(s.materials[s.objects[0].material].color);
    EXPECT_EQ(f.spec.kind, PatternKind::function);
    // At x = -3.5: mod -1.5, ceil -3, floor -4, int 3, div -1: 1.5; over the image's 320.
    EXPECT_NEAR(f.spec.function->value(-3.5, 0, 0), 1.5 / 320, 1e-12);
    EXPECT_NEAR(pattern_value(f.spec, {-3.5f, 0, 0}), 1.5 / 320, 1e-6);
    // 3x at x = 0.25 is 0.75; at 0.5, 1.5 wraps round to 0.5, and at -0.1, -0.3 to 0.7.
    const PatternTexture& triple =
        *std::get<PatternTexturePtr>(s.materials[s.objects[1].material].color);
    EXPECT_NEAR(pattern_value(triple.spec, {0.25f, 0, 0}), 0.75, 1e-6);
    EXPECT_NEAR(pattern_value(triple.spec, {0.5f, 0, 0}), 0.5, 1e-6);
    EXPECT_NEAR(pattern_value(triple.spec, {-0.1f, 0, 0}), 0.7, 1e-6);
    EXPECT_NE(error_of("sphere { 0, 1 pigment { function { select(x, 0, 1) } } }")
                  .find("scene.pov:1:25: error: the pigment's function uses select, which glint "
                        "does not compute yet"),
              std::string::npos);
}

// warp { turbulence }: the pattern's turbulence, with the transforms written before it beyond
// it (the point turbulence moved goes through them); uv_mapping, in the pigment or the texture:
// the pattern over the surface's (u, v, 0), placed by the pigment's transforms only.
TEST(PovScene, WarpTurbulenceAndUvMappedPatterns) {
    const Scene s = parse(R"(
        sphere { 0, 1 pigment { gradient x scale 2 warp { turbulence <0.5, 0, 0> octaves 3 omega 0.25 }
                                translate x } }
        sphere { 0, 1 pigment { uv_mapping gradient x scale 0.5 } translate y * 3 }
        sphere { 0, 1 texture { uv_mapping pigment { checker pigment { rgb 1 } pigment { rgb 0 } } } })");
    const PatternTexture& warped =
        *std::get<PatternTexturePtr>(s.materials[s.objects[0].material].color);
    EXPECT_TRUE(warped.spec.warped);
    EXPECT_EQ(warped.spec.turbulence, (Vector3{0.5f, 0, 0}));
    EXPECT_EQ(warped.spec.octaves, 3);
    EXPECT_EQ(warped.spec.omega, 0.25f);
    // Before the warp, scale 2: its inverse halves the turbulent point. After it, translate x.
    EXPECT_EQ(warped.spec.after_turbulence(Point3{1, 0, 0}), (Point3{0.5f, 0, 0}));
    EXPECT_EQ(warped.to_pattern(Point3{1, 0, 0}), (Point3{0, 0, 0}));
    const PatternTexture& on_uv =
        *std::get<PatternTexturePtr>(s.materials[s.objects[1].material].color);
    EXPECT_TRUE(on_uv.uv_mapping);
    // Through the pigment's transforms (scale 0.5, and the object's translate written after it),
    // as POV-Ray moves them; not through where the object lies.
    EXPECT_EQ(on_uv.to_pattern(Point3{0.5f, 0, 0}), (Point3{1, -6, 0}));
    EXPECT_TRUE(std::get<PigmentMapPtr>(s.materials[s.objects[2].material].color)->uv_mapping);
    EXPECT_EQ(uv_needed(s.materials[s.objects[2].material].color), Uv::compute);
    EXPECT_NE(error_of("sphere { 0, 1 pigment { gradient x warp { repeat x } } }")
                  .find("pigment pattern \"warp\" is not supported yet"),
              std::string::npos);
}

// isosurface: the function less the threshold as glint's implicit surface, within its
// container: intersected with it when closed, clipped by it (or bounded, a box) when open.
// Functions are written out: built-ins, declared floats, declared functions with their own
// parameters, functions.inc's internal ones.
TEST(PovScene, IsosurfacesAreImplicitSurfacesInTheirContainers) {
    const Scene s = parse(R"(
        #declare R = 0.5;
        #declare f_sphere = function { internal(61) }
        #declare Shifted = function(a, b, c, k) { f_sphere(a - k, b, c, R) }
        isosurface { function { Shifted(x, y, z, 1) } contained_by { box { -2, 2 } } }
        isosurface { function { pow(x, 2) + y*y + z^2 } threshold 1 open
                     contained_by { sphere { 0, 2 } } }
        isosurface { function { y - ln(exp(tan(x) * 0)) - max(-5, u, -3) } open }
        #declare f_noise3d = function { internal(76) }
        isosurface { function { f_noise3d(x, 2 * y, z) - 0.5 } })");
    ASSERT_EQ(s.objects.size(), 4u);
    const auto* closed = std::get_if<Csg>(&s.objects[0].shape);
    ASSERT_TRUE(closed);
    EXPECT_EQ(closed->operation, CsgOperation::intersection);
    const auto* surface = std::get_if<ImplicitSurface>(closed->a.get());
    ASSERT_TRUE(surface);
    EXPECT_NEAR(surface->f->value(1, 0, 0), -0.5, 1e-12);  // the centre of a sphere at x = 1
    EXPECT_NEAR(surface->f->value(1, 2, 0), 1.5, 1e-12);
    EXPECT_TRUE(std::holds_alternative<Box>(*closed->b));
    const auto* clipped = std::get_if<Csg>(&s.objects[1].shape);
    ASSERT_TRUE(clipped);
    EXPECT_EQ(clipped->operation, CsgOperation::clip);
    EXPECT_NEAR(std::get<ImplicitSurface>(*clipped->a).f->value(1, 1, 1), 3 - 1, 1e-12);
    EXPECT_TRUE(std::holds_alternative<Sphere>(*clipped->b));
    // Open in POV-Ray's default box: the surface alone, bounded by it. u is x: max(-5, -4, -3).
    const auto& plain = std::get<ImplicitSurface>(s.objects[2].shape);
    EXPECT_NEAR(plain.f->value(-4, 0.25, 0), 0.25 + 3, 1e-12);
    EXPECT_EQ(plain.region.max, (Point3{1, 1, 1}));
    // POV-Ray's f_noise3d, in [0, 1]: glint's noise mapped there.
    const auto& noisy = std::get<ImplicitSurface>(*std::get<Csg>(s.objects[3].shape).a);
    EXPECT_NEAR(noisy.f->value(0.3, 0.2, 0.7), 0.5 * perlin_noise(Point3{0.3f, 0.4f, 0.7f}), 1e-7);

    EXPECT_NE(error_of("#declare N = function { internal(80) }\n"
                       "isosurface { function { y + N(x, y, z) } }")
                  .find("scene.pov:2:14: error: the isosurface's function uses internal(80), "
                        "which glint does not compute yet"),
              std::string::npos);
    EXPECT_NE(error_of("isosurface { function { select(x, 1, 2) } }")
                  .find("uses select, which glint does not compute yet"),
              std::string::npos);
    EXPECT_NE(error_of("isosurface { function { x < 1 } }")
                  .find("scene.pov:1:27: error: comparisons and logic (<) in a function are not "
                        "supported yet"),
              std::string::npos);
    EXPECT_NE(error_of("#declare F = function(a) { a }\nisosurface { function { F(x, y) } }")
                  .find("scene.pov:2:25: error: \"F\" takes 1 arguments, got 2"),
              std::string::npos);
    EXPECT_NE(error_of("isosurface { function { " + std::string(300, '(') + "x" +
                       std::string(300, ')') + " } }")
                  .find("nested more than 200 levels deep"),
              std::string::npos);
    EXPECT_NE(error_of("isosurface { function { w } }")
                  .find("\"w\" is not a parameter, a declared float or a function"),
              std::string::npos);
    EXPECT_NE(error_of("isosurface { function { x } contained_by { cone { 0, 1, y, 0 } } }")
                  .find("contained_by holds a box or a sphere, got \"cone\""),
              std::string::npos);
}

// An inverse operand is the rest of space: intersection takes it away, difference keeps it; an
// inverse plane is the other half-space.
TEST(PovScene, InverseOperandsTurnTheirCsgOver) {
    const Scene s = parse(R"(
        plane { y, 1 inverse }
        intersection { box { -1, 1 } sphere { 0, 1.2 inverse } }
        difference { box { -1, 1 } plane { y, 0 inverse } })");
    ASSERT_EQ(s.objects.size(), 3u);
    const auto& plane = std::get<Plane>(s.objects[0].shape);
    EXPECT_EQ(plane.normal, (Normal3{0, -1, 0}));
    EXPECT_EQ(plane.point, (Point3{0, 1, 0}));
    EXPECT_EQ(std::get<Csg>(s.objects[1].shape).operation, CsgOperation::difference);
    // The plane turned over: the difference takes the upper half-space away.
    EXPECT_EQ(std::get<Csg>(s.objects[2].shape).operation, CsgOperation::difference);
    // The box's corners are left, outside the sphere; the difference keeps its lower half.
    const Ray corner{{0.95f, 0.95f, -5}, {0, 0, 1}};
    EXPECT_TRUE(intersect(s.objects[1].shape, corner, {0, kInfinity}).has_value());
    EXPECT_FALSE(intersect(s.objects[1].shape, Ray{{0, 0, -5}, {0, 0, 1}}, {0, kInfinity}));
    EXPECT_FALSE(intersect(s.objects[2].shape, Ray{{0, 0.5f, -5}, {0, 0, 1}}, {0, kInfinity}));
    EXPECT_TRUE(intersect(s.objects[2].shape, Ray{{0, -0.5f, -5}, {0, 0, 1}}, {0, kInfinity}));
    EXPECT_NE(error_of("merge { sphere { 0, 1 } sphere { x, 1 inverse } }")
                  .find("supported only as an operand of intersection, or of difference after its "
                        "first"),
              std::string::npos);
}

// clipped_by keeps the surface inside the clipping objects, which are written in the space the
// object has reached and move with its later transforms; a clipped union clips each object.
TEST(PovScene, ClippedByCutsSurfacesOpen) {
    const Scene s = parse(R"(
        sphere { 0, 1 translate x * 3 clipped_by { plane { y, 0 } } translate y * 5 }
        union { sphere { 0, 1 } sphere { z * 4, 1 } clipped_by { plane { -y, 0 } } })");
    ASSERT_EQ(s.objects.size(), 3u);
    // Down onto the bowl at (3, 5, 0): its top is cut away, so the ray meets the inside of its
    // lower half at y = 4, 6 below the start.
    const Ray down{{3, 10, 0}, {0, -1, 0}};
    const auto bowl = intersect(s.objects[0].shape, down, {0, kInfinity});
    ASSERT_TRUE(bowl.has_value());
    EXPECT_NEAR(bowl->t, 6, 1e-4);
    // The union's spheres keep their upper halves only: from below, a ray meets the inside of
    // the top at y = 1.
    for (std::size_t i = 1; i < 3; ++i) {
        const float z = i == 1 ? 0 : 4;
        const auto top = intersect(s.objects[i].shape, Ray{{0, -5, z}, {0, 1, 0}}, {0, kInfinity});
        ASSERT_TRUE(top.has_value());
        EXPECT_NEAR(top->t, 6, 1e-4);
    }
    EXPECT_NE(error_of("sphere { 0, 1 clipped_by { } }").find("clipped_by needs objects inside it"),
              std::string::npos);
    // clipped_by { bounded_by } clips by the bounding objects.
    const Scene bounded =
        parse("sphere { 0, 1 bounded_by { box { -1, <1, 0.3, 1> } } clipped_by { bounded_by } }");
    EXPECT_EQ(std::get<Csg>(bounded.objects[0].shape).operation, CsgOperation::clip);
}

// quadric, cubic, quartic and poly are glint's quadric and implicit surfaces, searched within
// the box of their bounded_by (or clipped_by) objects, or of the other operands of their
// intersection; an unbounded one stops the scene only where it is placed.
TEST(PovScene, PolynomialSurfacesAreSearchedWithinTheirBounds) {
    const Scene s = parse(R"(
        #declare Unused = quadric { <1, 1, 0>, <0, 0, 0>, <0, 0, 0>, -1 }
        quartic { <1, 0, 0, 0, 2, 0, 0, 2, 0, -104, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
                   1, 0, 0, 2, 0, 56, 0, 0, 0, 0, 1, 0, -104, 0, 784> sturm
                  bounded_by { sphere { 0, 10 } } translate z * 20 }
        quadric { <1, 1, 1>, <0, 0, 0>, <0, 0, 0>, -4 clipped_by { box { -3, 3 } } }
        intersection { poly { 2, <1, 0, 0, 0, 1, 0, 0, 0, 0, -1> } box { -2, 2 } })");
    ASSERT_EQ(s.objects.size(), 3u);
    const auto& torus = std::get<ImplicitSurface>(*std::get<Transformed>(s.objects[0].shape).shape);
    EXPECT_EQ(torus.region.min, (Point3{-10, -10, -10}));
    EXPECT_EQ(torus.region.max, (Point3{10, 10, 10}));
    // Along x through the torus's centre plane at z = 20: the tube's outside at
    // sqrt(40) + sqrt(12) = 9.78888.
    const auto hit = intersect(s.objects[0].shape, Ray{{-20, 0, 20}, {1, 0, 0}}, {0, kInfinity});
    ASSERT_TRUE(hit.has_value());
    EXPECT_NEAR(hit->t, 20 - 9.78888, 1e-3);
    // The sphere of radius 2 as a quadric, clipped by its box.
    const auto& sphere = std::get<Csg>(s.objects[1].shape);
    EXPECT_EQ(std::get<Quadric>(*sphere.a).clip.max, (Point3{3, 3, 3}));
    const auto front = intersect(s.objects[1].shape, Ray{{0, 0, -5}, {0, 0, 1}}, {0, kInfinity});
    ASSERT_TRUE(front.has_value());
    EXPECT_NEAR(front->t, 3, 1e-4);
    // The cylinder x^2 + y^2 = 1 cut to the box's height.
    const auto side = intersect(s.objects[2].shape, Ray{{-5, 0, 0}, {1, 0, 0}}, {0, kInfinity});
    ASSERT_TRUE(side.has_value());
    EXPECT_NEAR(side->t, 4, 1e-3);
    EXPECT_NE(error_of("quartic { <1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, "
                       "1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, -1> }")
                  .find("POV-Ray's quartic needs bounded_by or clipped_by in glint"),
              std::string::npos);
}

// prism is glint's prism: the outlines of its spline in the x-z plane, swept along y between its
// heights in either order; `open` leaves the caps off.
TEST(PovScene, PrismsSweepTheirSplinesOutlines) {
    const Scene s = parse(R"(
        prism { linear_sweep linear_spline 1, -1, 10,
                <-2, -2>, <2, -2>, <2, 2>, <-2, 2>, <-2, -2>,
                <-1, -1>, <1, -1>, <1, 1>, <-1, 1>, <-1, -1> }
        prism { bezier_spline 0, 1, 4, <0, 0>, <0, 1>, <1, 1>, <1, 0> open sturm }
        prism { -0.5, 0.5, (2 < 3) + 3 <-1, -0.3>, <1, 0>, <-1, 0.3>, <-1, -0.3> })");
    ASSERT_EQ(s.objects.size(), 3u);
    // A count is followed by its points: `4 <-1, ...` is not a comparison.
    EXPECT_EQ(std::get<Prism>(s.objects[2].shape).profile->edges.size(), 3u);
    const auto& frame = std::get<Prism>(s.objects[0].shape);
    EXPECT_EQ(frame.bottom, -1);
    EXPECT_EQ(frame.top, 1);
    EXPECT_EQ(frame.profile->edges.size(), 8u);
    // Down the hole: nothing; down the frame: the top cap.
    EXPECT_FALSE(intersect(s.objects[0].shape, Ray{{0, 5, 0}, {0, -1, 0}}, {0, kInfinity}));
    const auto hit = intersect(s.objects[0].shape, Ray{{1.5f, 5, 0}, {0, -1, 0}}, {0, kInfinity});
    ASSERT_TRUE(hit.has_value());
    EXPECT_FLOAT_EQ(hit->t, 4);
    EXPECT_TRUE(std::get<Prism>(s.objects[1].shape).open);
    EXPECT_EQ(s.warnings.size(), 1u);  // the Bezier outline, closed by a straight edge
    EXPECT_NE(error_of("prism { cubic_spline 0, 1, 3, <0, 0>, <1, 0>, <0, 1> }")
                  .find("prism: a cubic spline needs at least 4 points, got 3"),
              std::string::npos);
}

// mesh2: shared arrays where nothing has indices of its own; three corners a face where normals
// or uvs do; a mesh for each texture of its texture_list, over the object's texture.
TEST(PovScene, Mesh2SharesOrSplitsItsArrays) {
    const Scene s = parse(R"(
        mesh2 { vertex_vectors { 4, <0, 0, 0>, <1, 0, 0>, <1, 1, 0>, <0, 1, 0> }
                normal_vectors { 4, z, z, z, <0, 1, -1> }
                face_indices { 2, <0, 1, 2>, <0, 2, 3> } }
        mesh2 { vertex_vectors { 4, <0, 0, 0>, <1, 0, 0>, <1, 1, 0>, <0, 1, 0> }
                normal_vectors { 1, -z }
                texture_list { 2, texture { pigment { rgb 1 } } texture { pigment { rgb 0 } } }
                face_indices { 3, <0, 1, 2>, 1, <0, 2, 3>, 0, <1, 2, 3> }
                normal_indices { 3, <0, 0, 0>, <0, 0, 0>, <0, 0, 0> }
                pigment { rgb <1, 0, 0> } })");
    ASSERT_EQ(s.objects.size(), 4u);
    const MeshData& shared = *std::get<TriangleMesh>(s.objects[0].shape).data;
    EXPECT_EQ(shared.positions.size(), 4u);
    EXPECT_EQ(shared.triangles.size(), 2u);
    EXPECT_NEAR(shared.normals[3].z, -1 / std::sqrt(2.0f), 1e-6);  // normalised as given
    // By texture index: the object's own (no index) first, then 0 and 1; three corners a face.
    const auto color_of = [&](std::size_t i) {
        return std::get<Color>(s.materials[s.objects[i].material].color);
    };
    EXPECT_EQ(color_of(1), (Color{1, 0, 0}));
    EXPECT_EQ(color_of(2), (Color{1, 1, 1}));
    EXPECT_EQ(color_of(3), (Color{0, 0, 0}));
    const MeshData& own = *std::get<TriangleMesh>(s.objects[1].shape).data;
    EXPECT_EQ(own.positions.size(), 3u);
    EXPECT_EQ(own.normals[0], (Normal3{0, 0, -1}));
    EXPECT_EQ(s.warnings.size(), 0u);
}

// height_field: grey levels as the file holds them (not linear light), or a palette image's
// indices, over the unit square, the image's bottom row at z = 0; two triangles a cell.
TEST(PovScene, HeightFieldsAreMeshesOfTheImagesLevels) {
    const std::filesystem::path folder = std::filesystem::path(GLINT_SOURCE_DIR) / "tests/data/pov";
    const ReadSandbox sandbox = make_read_sandbox(folder / "scene.pov");
    const Scene s = parse_pov_scene(R"(
        height_field { png "heights" }
        height_field { png "heights-palette.png" smooth water_level 0.6 })",
                                    folder / "scene.pov", sandbox);
    ASSERT_EQ(s.objects.size(), 2u);
    const MeshData& grey = *std::get<TriangleMesh>(s.objects[0].shape).data;
    ASSERT_EQ(grey.positions.size(), 6u);
    EXPECT_EQ(grey.triangles.size(), 4u);
    // The bottom row (64, 32, 16) at z = 0, the top row (0, 128, 255) at z = 1.
    EXPECT_EQ(grey.positions[0], (Point3{0, 64 / 255.0f, 0}));
    EXPECT_NEAR(grey.positions[4].y, 128 / 255.0f, 1e-6);
    EXPECT_NEAR(grey.positions[5].y, 1, 1e-5);
    EXPECT_TRUE(grey.normals.empty());
    const MeshData& indexed = *std::get<TriangleMesh>(s.objects[1].shape).data;
    EXPECT_NEAR(indexed.positions[5].y, 255 / 256.0f, 1e-6);  // index 255 of 256
    EXPECT_NEAR(indexed.positions[2].y, 16 / 256.0f, 1e-6);
    EXPECT_EQ(indexed.normals.size(), 6u);
    EXPECT_EQ(indexed.triangles.size(), 1u);  // the three wholly under water: gone
    for (const Normal3& n : indexed.normals) EXPECT_GT(n.y, 0);
}

// superellipsoid { <e, n> }: (|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n) - 1 in the unit cube.
TEST(PovScene, ASphereSweepIsTheMergeOfItsSpheresAndCones) {
    // `0.5 <1, 0, 0>`: the vector after an item's float starts the next sphere, as POV-Ray
    // reads it, rather than comparing.
    const Scene s = parse(R"(
        sphere_sweep { linear_spline 3, <-1, 0, 0>, 0.5 <1, 0, 0>, 0.5, <1, 2, 0>, 0.25
                       tolerance 1e-6 translate z })");
    ASSERT_EQ(s.objects.size(), 1u);
    // Down onto the straight piece's top at x = 0: the cylinder of radius 0.5, moved by z.
    const auto top = intersect(s.objects[0].shape, Ray{{0, 5, 1}, {0, -1, 0}}, {0, kInfinity});
    ASSERT_TRUE(top.has_value());
    EXPECT_NEAR(top->t, 4.5f, 1e-5f);
    // Along the path from inside: no inner surface where the pieces meet, out at the first
    // sphere's far side.
    const auto out = intersect(s.objects[0].shape, Ray{{0.5f, 0, 1}, {-1, 0, 0}}, {0, kInfinity});
    ASSERT_TRUE(out.has_value());
    EXPECT_NEAR(out->t, 2, 1e-5f);
    EXPECT_NE(error_of("sphere_sweep { cubic_spline 3, <0, 0, 0>, 1, <1, 0, 0>, 1, <2, 0, 0>, 1 }")
                  .find("sphere_sweep cubic_spline needs at least 4 spheres, got 3"),
              std::string::npos);
}

TEST(PovScene, MediaFillTheirObjectsAsGlintsOwn) {
    const Scene s = parse(R"(
        #declare Glow = density { spherical density_map { [0 rgb 0] [1 rgb 2] } }
        #declare Haze = media { scattering { 5, <0.1, 0.2, 0.3> eccentricity 0.4 extinction 0.5 } }
        sphere { 0, 1 pigment { rgbt 1 } hollow
                 interior { media { emission 0.5 absorption <0.1, 0, 0> intervals 2 samples 3
                                    method 2 density { Glow } }
                            media { Haze } }
                 scale 2 translate x })");
    ASSERT_EQ(s.objects.size(), 1u);
    const Material& m = s.materials[s.objects[0].material];
    EXPECT_TRUE(m.hollow);
    ASSERT_EQ(m.media.size(), 2u);
    const Medium& glow = m.media[0];
    EXPECT_EQ(glow.emission, Color::gray(0.5f));
    EXPECT_EQ(glow.absorption, (Color{0.1f, 0, 0}));
    EXPECT_EQ(glow.samples, 6);  // intervals x samples with method 2
    ASSERT_EQ(glow.density.size(), 1u);
    // The density moves with the sphere: at its middle (1, 0, 0) the spherical pattern is 1,
    // the map's 2; half way out, 0.5 and 1; outside, 0.
    EXPECT_NEAR(density_at(glow, {1, 0, 0}).r, 2, 1e-5f);
    EXPECT_NEAR(density_at(glow, {1, 1, 0}).g, 1, 1e-5f);
    EXPECT_NEAR(density_at(glow, {3.5f, 0, 0}).b, 0, 1e-5f);
    const Medium& haze = m.media[1];
    EXPECT_EQ(haze.phase, PhaseKind::henyey_greenstein);
    EXPECT_EQ(haze.scattering, (Color{0.1f, 0.2f, 0.3f}));
    EXPECT_FLOAT_EQ(haze.eccentricity, 0.4f);
    EXPECT_FLOAT_EQ(haze.extinction, 0.5f);
    EXPECT_EQ(haze.samples, 8);  // POV-Ray's 1 interval, 1 sample, method 3 of 2^3
    EXPECT_TRUE(haze.density.empty());
}

TEST(PovScene, MediaOutsideObjectsAreTheAtmosphere) {
    const Scene s = parse(R"(
        media { scattering { 4, 0.02 } absorption 0.01 intervals 10 samples 2 method 1 }
        light_source { <0, 10, 0> rgb 1 media_interaction off }
        light_source { <0, 10, 5> rgb 1 spotlight point_at 0 })");
    ASSERT_EQ(s.atmosphere.size(), 1u);
    EXPECT_EQ(s.atmosphere[0].phase, PhaseKind::rayleigh);
    EXPECT_EQ(s.atmosphere[0].scattering, Color::gray(0.02f));
    EXPECT_EQ(s.atmosphere[0].samples, 20);
    ASSERT_EQ(s.lights.size(), 2u);
    EXPECT_FALSE(scatters_in_media(s.lights[0]));
    EXPECT_TRUE(scatters_in_media(s.lights[1]));
}

TEST(PovScene, SuperellipsoidsAreImplicitSurfaces) {
    const Scene s = parse("superellipsoid { <1, 1> } superellipsoid { <0.5, 2> }");
    ASSERT_EQ(s.objects.size(), 2u);
    const auto& sphere = std::get<ImplicitSurface>(s.objects[0].shape);
    EXPECT_NEAR(sphere.f->value(1, 0, 0), 0, 1e-12);
    EXPECT_NEAR(sphere.f->value(0.5, 0.5, 0), -0.5, 1e-12);  // a sphere: x^2 + y^2 + z^2 - 1
    const auto& other = std::get<ImplicitSurface>(s.objects[1].shape);
    // (0.5^4 + 0.5^4)^(1/4) + 0.5^1 - 1 = 0.125^0.25 - 0.5
    EXPECT_NEAR(other.f->value(0.5, 0.5, 0.5), std::pow(0.125, 0.25) - 0.5, 1e-12);
    EXPECT_TRUE(bounds(s.objects[1].shape).contains({1, 1, 1}));
    EXPECT_NE(error_of("superellipsoid { <0, 1> }")
                  .find("superellipsoid's e and n must be in [0.001, 1000]"),
              std::string::npos);
}

// blob: threshold - the components' fields strength (1 - d^2/r^2)^2, d to a sphere's centre or
// a cylinder's axis (round at its ends), each placed by its own transforms.
TEST(PovScene, BlobsAreTheirFieldsAboveTheThreshold) {
    const Scene s = parse(R"(
        blob { threshold 0.6 sphere { 0, 1, 1 scale 2 translate x * 5 }
               cylinder { <0, 0, 0>, <2, 0, 0>, 1, strength 1 } component 0.5, 1, <0, 3, 0>
               sphere { <1, 0, 0>, 0.5, -1 } sturm })");
    ASSERT_EQ(s.objects.size(), 1u);
    const auto& blob = std::get<ImplicitSurface>(s.objects[0].shape);
    const auto f = [&](double x, double y, double z) { return blob.f->value(x, y, z); };
    EXPECT_NEAR(f(5, 0, 0), 0.6 - 1, 1e-12);                       // the scaled sphere's centre
    EXPECT_NEAR(f(6, 0, 0), 0.6 - 0.5625, 1e-12);                  // halfway out of its radius 2
    EXPECT_NEAR(f(0.5, 0.5, 0), 0.6 - 0.5625, 1e-12);              // half a radius off the axis
    EXPECT_NEAR(f(-0.5, 0, 0), 0.6 - 0.5625, 1e-12);               // beyond the end a: round
    EXPECT_NEAR(f(0, 3, 0), 0.6 - 0.5, 1e-12);                     // the old form: strength 0.5
    EXPECT_NEAR(f(1, 0.25, 0), 0.6 - 0.87890625 + 0.5625, 1e-12);  // less the negative sphere's
    const Bounds3 b = bounds(s.objects[0].shape);
    EXPECT_LE(b.min.x, -1);
    EXPECT_GE(b.max.x, 7);
    EXPECT_NE(error_of("blob { sphere { 0, 1, -1 } }")
                  .find("a blob needs a component of positive strength"),
              std::string::npos);
    EXPECT_NE(
        error_of("blob { threshold 0 sphere { 0, 1, 1 } }").find("a blob's threshold must be > 0"),
        std::string::npos);
}

// image_map: projected from the object's space through its pigment's transforms, or on the
// surface's uv; filter and transmit all let light through; the file found beside the scene.
TEST(PovScene, ImageMapsProjectTheirImage) {
    const std::filesystem::path folder = std::filesystem::path(GLINT_SOURCE_DIR) / "tests/data/pov";
    const ReadSandbox sandbox = make_read_sandbox(folder / "scene.pov");
    const Scene s = parse_pov_scene(R"(
        sphere { 0, 1 pigment { image_map { png "grid" map_type 1 once interpolate 2
                                            transmit all 0.25 } scale 2 } translate x * 3 }
        box { 0, 1 pigment { uv_mapping image_map { png "grid.png" } } })",
                                    folder / "scene.pov", sandbox);
    ASSERT_EQ(s.objects.size(), 2u);
    const Material& projected = s.materials[s.objects[0].material];
    const auto* image = std::get_if<ProjectedImagePtr>(&projected.color);
    ASSERT_TRUE(image);
    EXPECT_EQ((*image)->projection, ImageProjection::spherical);
    EXPECT_TRUE((*image)->once);
    EXPECT_EQ((*image)->image.filter, TextureFilter::bilinear);
    EXPECT_EQ((*image)->image.image->level(0).width, 16);
    const Point3 q = (*image)->to_projection(Point3{5, 0, 0});  // scaled by 2, then moved by 3
    EXPECT_NEAR(q.x, 1, 1e-6);
    EXPECT_FLOAT_EQ(projected.transmit, 0.25f);
    const Material& on_uv = s.materials[s.objects[1].material];
    ASSERT_TRUE(std::holds_alternative<ImageTexture>(on_uv.color));
    EXPECT_EQ(std::get<ImageTexture>(on_uv.color).filter, TextureFilter::nearest);
}

// An image's texels, read as linear light, are encoded into the scene's working space, as
// POV-Ray does: sRGB's for a scene older than 3.7 without assumed_gamma, 1 / 2 for gamma 2.
TEST(PovScene, ImagesAreEncodedIntoTheWorkingSpace) {
    const std::filesystem::path folder = std::filesystem::path(GLINT_SOURCE_DIR) / "tests/data/pov";
    const ReadSandbox sandbox = make_read_sandbox(folder / "scene.pov");
    const auto texels = [&](const std::string& settings) {
        const Scene s = parse_pov_scene(
            settings + " box { 0, 1 pigment { uv_mapping image_map { png \"grid.png\" } } }",
            folder / "scene.pov", sandbox);
        return std::get<ImageTexture>(s.materials[s.objects[0].material].color)
            .image->base()
            .pixels;
    };
    const std::vector<Color> linear = texels("#version 3.7;");
    const std::vector<Color> old = texels("#version 3.6;");
    const std::vector<Color> two = texels("#version 3.7; global_settings { assumed_gamma 2 }");
    for (std::size_t i = 0; i < linear.size(); i += 37) {
        EXPECT_NEAR(old[i].g, linear_to_srgb(linear[i].g), 1e-6f);
        EXPECT_NEAR(two[i].g, std::sqrt(linear[i].g), 1e-6f);
    }
}

// text is a union of prisms, a letter each, standing in the x-y plane from z = 0 to the
// thickness; the font comes from beside the scene (here POV-Ray's timrom.ttf of tests/data/pov).
TEST(PovScene, TextIsAPrismALetter) {
    const std::filesystem::path folder = std::filesystem::path(GLINT_SOURCE_DIR) / "tests/data/pov";
    const ReadSandbox sandbox = make_read_sandbox(folder / "scene.pov");
    const Scene s = parse_pov_scene(R"(text { ttf "timrom.ttf" "I o" 0.25, 0 })",
                                    folder / "scene.pov", sandbox);
    ASSERT_EQ(s.objects.size(), 2u);  // the space has no letter
    // Along z through the I's stem: its front at z = 0, seen from -z.
    const auto front =
        intersect(s.objects[0].shape, Ray{{0.15f, 0.3f, -5}, {0, 0, 1}}, {0, kInfinity});
    ASSERT_TRUE(front.has_value());
    EXPECT_NEAR(front->t, 5, 1e-5);
    const auto back =
        intersect(s.objects[0].shape, Ray{{0.15f, 0.3f, 5}, {0, 0, -1}}, {0, kInfinity});
    ASSERT_TRUE(back.has_value());
    EXPECT_NEAR(back->t, 4.75, 1e-5);
    // Through the o's hole: nothing; through its ring: the letter.
    const Bounds3 o = bounds(s.objects[1].shape);
    const float middle_x = (o.min.x + o.max.x) / 2, middle_y = (o.min.y + o.max.y) / 2;
    EXPECT_FALSE(
        intersect(s.objects[1].shape, Ray{{middle_x, middle_y, -5}, {0, 0, 1}}, {0, kInfinity}));
    EXPECT_TRUE(intersect(s.objects[1].shape, Ray{{o.min.x + 0.02f, middle_y, -5}, {0, 0, 1}},
                          {0, kInfinity}));
    EXPECT_NEAR(o.min.z, 0, 1e-6);
    EXPECT_NEAR(o.max.z, 0.25, 1e-6);
}

// Arrays of items: object { Shapes[I] }, texture { Looks[I] }; default { } as a statement; and
// modifiers glint reads past with a warning once.
TEST(PovScene, ArrayElementsDefaultBlocksAndModifiersReadPast) {
    const Scene s = parse(R"(
        #declare Shapes = array[2] { sphere { 0, 1 }, box { -1, 1 } }
        #declare Looks = array[2] { texture { pigment { rgb x } }, texture { pigment { rgb y } } }
        default { finish { ambient 0 } }
        object { Shapes[1] texture { Looks[1] } no_reflection photons { target } }
        object { Shapes[0] texture { Looks[0] } no_reflection }
        sphere { x * 3, 1 }
        light_source { <0, 5, 0>, 1 photons { refraction on } })");
    ASSERT_EQ(s.objects.size(), 3u);
    EXPECT_TRUE(std::holds_alternative<Box>(s.objects[0].shape));
    EXPECT_EQ(std::get<Color>(s.materials[s.objects[0].material].color), (Color{0, 1, 0}));
    // The default's finish goes to objects without a texture of their own.
    EXPECT_EQ(s.materials[s.objects[2].material].ka, 0);
    EXPECT_TRUE(std::holds_alternative<Sphere>(s.objects[1].shape));
    std::size_t read_past = 0;
    for (const std::string& w : s.warnings)
        read_past += w.find("is read past") != std::string::npos;
    EXPECT_EQ(read_past, 3u);  // no_reflection once, photons in an object and in a light
    EXPECT_NE(
        error_of("#declare Shapes = array[2] { sphere { 0, 1 }, 4 }\n"
                 "object { Shapes[1] }")
            .find("this element of Shapes holds another kind of value than its other elements"),
        std::string::npos);
}

// POV-Ray's infinite quadrics (shapes.inc's Cylinder_X and friends): an intersection of them
// is bounded by their insides' boxes, and one alone is cut far out.
TEST(PovScene, UnboundedQuadricsAreBoundedByWhatBoundsTheirInsides) {
    const Scene s = parse(R"(
        #declare Cylinder_X = quadric { <0, 1, 1>, <0, 0, 0>, <0, 0, 0>, -1 }
        #declare Cylinder_Y = quadric { <1, 0, 1>, <0, 0, 0>, <0, 0, 0>, -1 }
        intersection { object { Cylinder_X } object { Cylinder_Y } translate z * 10 }
        object { Cylinder_X scale 2 translate y * 10 }
        intersection { object { Cylinder_Y } plane { y, 3 } plane { -y, 0 } translate x * 10 })");
    ASSERT_EQ(s.objects.size(), 3u);
    // The two cylinders cross in [-1, 1]^3: along x through the middle, the bicylinder's side.
    const Bounds3 both = bounds(s.objects[0].shape);
    EXPECT_NEAR(both.min.x, -1, 1e-3);  // loosened by 1e-4 of its size
    EXPECT_NEAR(both.max.z, 11, 1e-3);
    auto hit = intersect(s.objects[0].shape, Ray{{-5, 0, 10}, {1, 0, 0}}, {0, kInfinity});
    ASSERT_TRUE(hit.has_value());
    EXPECT_NEAR(hit->t, 4, 1e-4);
    // The lone cylinder, radius 2 about y = 10, reaches far along x.
    const Bounds3 lone = bounds(s.objects[1].shape);
    EXPECT_NEAR(lone.min.y, 8, 1e-3);
    EXPECT_GE(lone.max.x, 1e5f);
    hit = intersect(s.objects[1].shape, Ray{{1000, 10, -5}, {0, 0, 1}}, {0, kInfinity});
    ASSERT_TRUE(hit.has_value());
    EXPECT_NEAR(hit->t, 3, 1e-3);
    // A cylinder between two planes: bounded by the planes' half-spaces.
    const Bounds3 cut = bounds(s.objects[2].shape);
    EXPECT_NEAR(cut.min.y, 0, 1e-3);
    EXPECT_NEAR(cut.max.y, 3, 1e-3);
}

// julia_fractal is glint's quaternion Julia set; other algebras and functions are named.
TEST(PovScene, JuliaFractalsAreGlintsJuliaSets) {
    const Scene s = parse(R"(
        julia_fractal { <-0.083, 0.0, -0.83, -0.025> quaternion sqr max_iteration 8
                        precision 20 slice <0, 0, 0, 1>, 0.1 })");
    ASSERT_EQ(s.objects.size(), 1u);
    const auto& julia = std::get<JuliaSet>(s.objects[0].shape);
    EXPECT_FLOAT_EQ(julia.c[2], -0.83f);
    EXPECT_EQ(julia.max_iterations, 8);
    EXPECT_FLOAT_EQ(julia.slice_w, 0.1f);
    EXPECT_NE(error_of("julia_fractal { <0.2, 0.1, 0.5, 0> hypercomplex }")
                  .find("\"hypercomplex\" is not supported in a julia_fractal yet"),
              std::string::npos);
}

// interior { dispersion D }: the index runs from ior / sqrt(D) at the red end (700 nm) to
// ior sqrt(D) at the violet (400 nm) on glint's Cauchy formula, rendered by the distributed
// integrator with at least dispersion_samples samples a pixel.
TEST(PovScene, DispersionIsCauchysFormulaThroughTheSpectrumsEnds) {
    const Scene s = parse(
        "sphere { 0, 1 pigment { rgbf 1 } interior { ior 1.5 dispersion 1.1 "
        "dispersion_samples 12 } }");
    const Material& m = s.materials[s.objects[0].material];
    EXPECT_EQ(m.dispersion.model, DispersionModel::cauchy);
    EXPECT_NEAR(refractive_index(m.dispersion, m.ior, 700), 1.5 / std::sqrt(1.1), 1e-5);
    EXPECT_NEAR(refractive_index(m.dispersion, m.ior, 400), 1.5 * std::sqrt(1.1), 1e-5);
    EXPECT_NEAR(m.ior, refractive_index(m.dispersion, m.ior, kReferenceWavelength), 1e-6);
    EXPECT_EQ(s.settings.integrator, IntegratorKind::distributed);
    EXPECT_EQ(s.settings.samples_per_pixel, 12);
    EXPECT_NE(error_of("sphere { 0, 1 interior { dispersion 0 } }")
                  .find("scene.pov:1:37: error: dispersion must be in (0.5, 2), got 0"),
              std::string::npos);
}

// A pigment's filter tints what it lets through by its colour, its transmit does not: the
// material's tint is filter's share of filter + transmit. interior { fade_distance fade_power
// fade_color } is glint's fade, POV-Ray's power 0 unless given.
TEST(PovScene, FilterIsTheTintAndTheInteriorsFadeIsGlintsFade) {
    const Scene s = parse(R"(
        sphere { 0, 1 pigment { rgbft <1, 0.5, 0, 0.6, 0.2> }
                 interior { fade_distance 2 fade_power 1001 fade_color <0.5, 1, 0> } }
        sphere { 0, 1 pigment { rgbt <1, 0, 0, 0.5> } interior { fade_distance 3 } })");
    ASSERT_EQ(s.materials.size(), 2u);
    const Material& filtered = s.materials[s.objects[0].material];
    EXPECT_FLOAT_EQ(filtered.transmit, 0.8f);
    EXPECT_FLOAT_EQ(filtered.tint, 0.75f);
    EXPECT_FLOAT_EQ(filtered.fade.distance, 2);
    EXPECT_FLOAT_EQ(filtered.fade.power, 1001);
    EXPECT_EQ(filtered.fade.color, (Color{0.5f, 1, 0}));
    const Material& clear = s.materials[s.objects[1].material];
    EXPECT_EQ(clear.tint, 0);
    EXPECT_FLOAT_EQ(clear.fade.distance, 3);
    EXPECT_EQ(clear.fade.power, 0);
    EXPECT_EQ(clear.fade.color, (Color{0, 0, 0}));
    EXPECT_NE(error_of("sphere { 0, 1 interior { fade_color <2, 0, 0> } }")
                  .find("scene.pov:1:37: error: fade colour's channels must be in [0, 1]"),
              std::string::npos);
}

// reflection { min max falloff fresnel metallic } and a reflection's colour: kr from min facing
// the viewer to max at grazing incidence, through the falloff or Fresnel's reflectance (from 0
// with one value), tinted by metallic; a coloured reflection is its greatest channel in that
// colour.
TEST(PovScene, ReflectionsVaryWithTheAngleAndHaveAColour) {
    const Scene s = parse(R"(
        sphere { 0, 1 finish { reflection <0.8, 0.4, 0.2> } }
        sphere { 0, 1 finish { reflection { 0.1, 0.6 falloff 2 metallic 0.5 } } }
        sphere { 0, 1 finish { reflection { 0.7 fresnel } } interior { ior 1.5 } }
        sphere { 0, 1 finish { reflection { 0.3 } } })");
    ASSERT_EQ(s.materials.size(), 4u);
    const Material& coloured = s.materials[s.objects[0].material];
    EXPECT_FLOAT_EQ(coloured.reflect, 0.8f);
    EXPECT_EQ(coloured.reflect_color, (Color{1, 0.5f, 0.25f}));
    EXPECT_FALSE(coloured.reflect_angular);
    const Material& falling = s.materials[s.objects[1].material];
    EXPECT_FLOAT_EQ(falling.reflect, 0.6f);
    ASSERT_TRUE(falling.reflect_angular);
    EXPECT_FLOAT_EQ(falling.reflect_angular->facing, 0.1f);
    EXPECT_FLOAT_EQ(falling.reflect_angular->falloff, 2);
    EXPECT_FALSE(falling.reflect_angular->fresnel);
    EXPECT_FLOAT_EQ(falling.reflect_metallic, 0.5f);
    const Material& glass = s.materials[s.objects[2].material];
    ASSERT_TRUE(glass.reflect_angular);
    EXPECT_EQ(glass.reflect_angular->facing, 0);
    EXPECT_TRUE(glass.reflect_angular->fresnel);
    EXPECT_FLOAT_EQ(glass.reflect, 0.7f);
    EXPECT_FALSE(s.materials[s.objects[3].material].reflect_angular);  // min = max
}

TEST(PovScene, MaterialsGiveTextureAndInterior) {
    const Scene s = parse(R"(
        #declare Glass = material { texture { pigment { rgbf <1, 0, 0, 0.5> } } interior { ior 1.5 } }
        sphere { 0, 1 material { Glass } }
        sphere { x * 3, 1 material { Glass interior { ior 1.2 } } })");
    ASSERT_EQ(s.objects.size(), 2u);
    const Material& a = s.materials[s.objects[0].material];
    EXPECT_EQ(std::get<Color>(a.color), (Color{1, 0, 0}));
    EXPECT_FLOAT_EQ(a.ior, 1.5f);
    EXPECT_FLOAT_EQ(a.transmit, 0.5f);
    EXPECT_FLOAT_EQ(s.materials[s.objects[1].material].ior, 1.2f);
}

// min_extent and max_extent: the corners of an object's bounding box, transforms and CSG
// included.
TEST(PovScene, ExtentsAreTheCornersOfAnObjectsBox) {
    const Scene s = parse(R"(
        #declare B = box { -1, <2, 3, 4> translate x }
        #declare I = intersection { sphere { 0, 2 } box { 0, 5 } }
        #debug vstr(3, min_extent(B), ",", 0, 0) #debug vstr(3, max_extent(B), ",", 0, 0)
        #debug vstr(3, min_extent(I), ",", 0, 0) #debug vstr(3, max_extent(I), ",", 0, 0)
        sphere { 0, 1 })");
    EXPECT_EQ(s.warnings, (std::vector<std::string>{"#debug: 0,-1,-1", "#debug: 3,3,4",
                                                    "#debug: 0,0,0", "#debug: 2,2,2"}));
}

TEST(PovScene, ACheckerOfTexturesIsACheckerOfTheirColours) {
    const Scene s = parse(R"(#version 3.7;
        plane { y, 0 texture { checker
            texture { pigment { rgb <1, 1, 1> } finish { ambient 0.3 diffuse 0.6 } }
            texture { pigment { rgb <0.1, 0.2, 0.3> } } scale 2 } })");
    ASSERT_EQ(s.objects.size(), 1u);
    const Material& m = s.materials[s.objects[0].material];
    const PatternTexture& checker = *std::get<PatternTexturePtr>(m.color);
    EXPECT_EQ(checker.spec.kind, PatternKind::checker);
    EXPECT_EQ(evaluate(checker, {0.5f, 0.5f, 0.5f}), (Color{1, 1, 1}));
    EXPECT_EQ(evaluate(checker, {2.5f, 0.5f, 0.5f}), (Color{0.1f, 0.2f, 0.3f}));
    EXPECT_FLOAT_EQ(m.ka, 0.3f);
    EXPECT_FLOAT_EQ(m.kd, 0.6f);
    EXPECT_NE(error_of("plane { y, 0 texture { checker texture { pigment { bozo } } "
                       "texture { pigment { rgb 1 } } } }")
                  .find("a checker of patterned textures is not supported yet"),
              std::string::npos);
}

// A folder the user allows to be read is a library path too (POV-Ray's +L).
TEST(PovScene, AllowedFoldersAreSearchedForIncludes) {
    const auto root =
        std::filesystem::temp_directory_path() /
        ("glint_pov_lib_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()));
    std::filesystem::create_directories(root / "scene");
    std::filesystem::create_directories(root / "lib");
    std::ofstream(root / "lib" / "ball.inc") << "#declare Ball = sphere { 0, 2 }";
    const std::string text = "#include \"ball.inc\" object { Ball }";
    const ReadSandbox allowed =
        make_read_sandbox(root / "scene" / "scene.pov", std::vector{root / "lib"});
    EXPECT_EQ(
        parse_pov_scene(text, (root / "scene" / "scene.pov").string(), allowed).objects.size(), 1u);
    const ReadSandbox alone = make_read_sandbox(root / "scene" / "scene.pov");
    try {
        parse_pov_scene(text, (root / "scene" / "scene.pov").string(), alone);
        ADD_FAILURE() << "ball.inc was found without its folder";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("cannot find the include file \"ball.inc\""),
                  std::string::npos);
    }
    std::filesystem::remove_all(root);
}

TEST(PovScene, FogsBecomeGlintsFogs) {
    const Scene s = parse(
        "#version 3.7;\n"
        "fog { distance 25 color rgbft <0.5, 0.6, 0.7, 0.2, 0.1> }\n"
        "fog { fog_type 2 distance 3 color rgb 1 fog_offset 0.5 fog_alt 2 up z "
        "turbulence 0.4 turb_depth 0.3 }\n"
        "fog { color rgb 1 }\n");
    ASSERT_EQ(s.fogs.size(), 2u);  // the one without a distance does nothing: left out
    EXPECT_EQ(s.fogs[0].kind, FogKind::constant);
    EXPECT_FLOAT_EQ(s.fogs[0].distance, 25);
    EXPECT_EQ(s.fogs[0].color, (Color{0.5f, 0.6f, 0.7f}));
    EXPECT_FLOAT_EQ(s.fogs[0].filter, 0.2f);
    EXPECT_FLOAT_EQ(s.fogs[0].transmit, 0.1f);
    EXPECT_EQ(s.fogs[1].kind, FogKind::ground);
    EXPECT_FLOAT_EQ(s.fogs[1].offset, 0.5f);
    EXPECT_FLOAT_EQ(s.fogs[1].altitude, 2);
    EXPECT_EQ(s.fogs[1].up, (Vector3{0, 0, 1}));
    EXPECT_EQ(s.fogs[1].turbulence, (Vector3{0.4f, 0.4f, 0.4f}));
    EXPECT_FLOAT_EQ(s.fogs[1].turbulence_depth, 0.3f);
    EXPECT_EQ(s.warnings.size(), 1u);
}

// Three layers, from the top: clear (rgbt 1), white half transmitting with diffuse 0.5 and
// ambient 0.3, and blue. The top's finish (diffuse 0.6, ambient 0.1) is the material's; the
// white's weighs it by 0.5 / 0.6 in the diffuse term and by 3 in the ambient one:
//   C = 0 + 1 (1 - 0.5) (0.5 / 0.6) (1, 1, 1) + 0.5 (0, 0, 1) = (5/12, 5/12, 11/12),
//   C_ambient = 0 + 1 (1 - 0.5) 3 (1, 1, 1) + 0.5 (0, 0, 1) = (1.5, 1.5, 2).
TEST(PovScene, LayeredTexturesLetTheLayersBelowShowThrough) {
    const Scene s = parse(R"(
        #version 3.7;
        #declare Base = texture { pigment { rgb <0, 0, 1> } }
            texture { pigment { rgbt <1, 1, 1, 0.5> } finish { diffuse 0.5 ambient 0.3 } }
        #declare Again = texture { Base scale 2 }
        sphere { 0, 1 texture { Again } texture { pigment { rgbt 1 } } }
        sphere { 0, 1 texture { Base } texture { pigment { rgb <1, 0, 0> } } }
        sphere { 0, 1 texture { Base } pigment { rgb <0, 1, 0> } })");
    ASSERT_EQ(s.objects.size(), 3u);
    const Material& layered = s.materials[s.objects[0].material];
    ASSERT_TRUE(std::holds_alternative<LayeredTexturePtr>(layered.color));
    const LayeredTexture& layers = *std::get<LayeredTexturePtr>(layered.color);
    EXPECT_EQ(layers.layers.size(), 3u);
    EXPECT_FALSE(layers.legacy_opacity);
    const Color c = evaluate(layered.color, SurfacePoint{});
    EXPECT_FLOAT_EQ(c.r, 5.0f / 12);
    EXPECT_FLOAT_EQ(c.g, 5.0f / 12);
    EXPECT_FLOAT_EQ(c.b, 11.0f / 12);
    const Color ambient = evaluate_layers(layers, SurfacePoint{}).ambient;
    EXPECT_FLOAT_EQ(ambient.r, 1.5f);
    EXPECT_FLOAT_EQ(ambient.b, 2);
    EXPECT_FLOAT_EQ(layered.kd, 0.6f);
    EXPECT_FLOAT_EQ(layered.ka, 0.1f);  // the opacity is the layers' own, not scaled again
    EXPECT_FLOAT_EQ(layered.transmit, 0);
    // An opaque layer hides what lies below it.
    EXPECT_EQ(std::get<Color>(s.materials[s.objects[1].material].color), (Color{1, 0, 0}));
    // A pigment after a layered texture is the top layer's, as in POV-Ray, which keeps its
    // finish.
    const Material& top = s.materials[s.objects[2].material];
    EXPECT_EQ(std::get<Color>(top.color), (Color{0, 1, 0}));
    EXPECT_FLOAT_EQ(top.kd, 0.5f);
    EXPECT_TRUE(s.warnings.empty());
}

// A texture written after another on an object is a layer over it, even after a transform, and
// is read from the default texture, not from the one below it.
TEST(PovScene, EveryTextureOnAnObjectIsALayer) {
    const Scene s = parse(R"(
        #version 3.7;
        #declare Shiny = sphere { 0, 1 texture { pigment { rgb <0, 0, 1> } finish { phong 1 } } }
        object { Shiny translate x texture { pigment { rgbf <1, 1, 1, 0.5> } } }
        object { Shiny texture { pigment { rgb 1 } } })");
    ASSERT_EQ(s.objects.size(), 2u);
    EXPECT_TRUE(
        std::holds_alternative<LayeredTexturePtr>(s.materials[s.objects[0].material].color));
    const Material& covered = s.materials[s.objects[1].material];
    EXPECT_EQ(std::get<Color>(covered.color), (Color{1, 1, 1}));
    EXPECT_FLOAT_EQ(covered.ks, 0);
}

// Scenes written for POV-Ray 3.6 or before get its opacity, 1 - (filter max(C) + transmit).
TEST(PovScene, OldScenesLayersTakeTheOldOpacity) {
    const Scene s = parse(R"(
        #version 3.6;
        sphere { 0, 1 texture { pigment { rgb 1 } } texture { pigment { rgbf <0.5, 0, 0, 0.5> } } })");
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_TRUE(
        std::get<LayeredTexturePtr>(s.materials[s.objects[0].material].color)->legacy_opacity);
}

TEST(PovScene, DefaultTexturesApplyToLaterObjectsWithoutOne) {
    const Scene s = parse(R"(
        sphere { 0, 1 }
        #default { pigment { rgb <1, 0, 0> } finish { ambient 0.3 } }
        sphere { 0, 1 }
        sphere { 0, 1 pigment { rgb 1 } }
        #declare Shiny = finish { phong 1 }
        sphere { 0, 1 texture { pigment { rgb 1 } finish { Shiny } } })");
    ASSERT_EQ(s.objects.size(), 4u);
    EXPECT_EQ(std::get<Color>(s.materials[s.objects[0].material].color), (Color{0, 0, 0}));
    const Material& red = s.materials[s.objects[1].material];
    EXPECT_EQ(std::get<Color>(red.color), (Color{1, 0, 0}));
    EXPECT_FLOAT_EQ(red.ka, 0.3f);
    EXPECT_EQ(std::get<Color>(s.materials[s.objects[2].material].color), (Color{1, 1, 1}));
    // A texture, pigment or finish written after #default starts from its values, as in POV-Ray.
    EXPECT_FLOAT_EQ(s.materials[s.objects[2].material].ka, 0.3f);
    EXPECT_FLOAT_EQ(s.materials[s.objects[3].material].ka, 0.3f);
    EXPECT_FLOAT_EQ(s.materials[s.objects[3].material].ks, 1);
}

}  // namespace
}  // namespace glint::pov_scene_test
