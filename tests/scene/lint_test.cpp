// Each lint rule on a small scene that breaks it and on one that keeps it.
#include "glint/scene/lint.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "glint/scene/yaml/yaml_scene_loader.h"

namespace glint {
namespace {

// A camera at (0, 1, -5) looking at the origin, a point light above, and the given sections.
Scene scene_with(const std::string& rest,
                 const std::string& lights = "lights: [{type: point, position: [0, 5, -3]}]\n",
                 const std::string& integrator = "whitted") {
    return parse_yaml_scene("image: {width: 40, height: 30, integrator: " + integrator +
                                "}\n"
                                "camera: {from: [0, 1, -5], at: [0, 0, 0], fov: 40}\n" +
                                lights + rest,
                            "lint.yaml");
}

Scene path_scene_with(const std::string& rest) {
    return scene_with(rest, "lights: [{type: point, position: [0, 5, -3]}]\n", "path");
}

std::vector<LintWarning> of_rule(const Scene& scene, std::string_view rule) {
    std::vector<LintWarning> out;
    for (LintWarning& w : lint_scene(scene))
        if (w.rule == rule) out.push_back(std::move(w));
    return out;
}

const std::string kBall = "objects: [{type: sphere, center: [0, 0, 0], radius: 1}]\n";

TEST(Lint, ARuleNamesEveryWarning) {
    const Scene scene =
        scene_with("objects: [{type: sphere, center: [0, 0, 0], radius: 1}]\n", "lights: []\n");
    for (const LintWarning& w : lint_scene(scene))
        EXPECT_NE(std::find(std::begin(kLintRules), std::end(kLintRules), w.rule),
                  std::end(kLintRules))
            << w.rule;
}

TEST(Lint, NoLightsAndNoEmittersWarns) {
    const auto warnings = of_rule(scene_with(kBall, ""), "no-lights");
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(warnings[0].subject, "scene");
}

TEST(Lint, AnEmittingObjectIsALight) {
    EXPECT_TRUE(of_rule(scene_with(kBall), "no-lights").empty());
    const Scene glowing = scene_with(
        "objects: [{type: sphere, center: [0, 0, 0], radius: 1, material: {emission: 1}}]\n", "");
    EXPECT_TRUE(of_rule(glowing, "no-lights").empty());
    // Seen glowing though it lights nothing, as dispersion.yaml's slit.
    const Scene seen = scene_with(
        "objects: [{type: sphere, center: [0, 0, 0], radius: 1, material: {emission: 1}, "
        "emits_light: false}]\n",
        "");
    EXPECT_TRUE(of_rule(seen, "no-lights").empty());
}

TEST(Lint, TheSkyLightsOnlyForThePhysicallyBasedIntegrators) {
    const Scene lit = parse_yaml_scene(
        "image: {width: 40, height: 30, integrator: path, background: [0.5, 0.6, 0.8]}\n"
        "camera: {from: [0, 1, -5], at: [0, 0, 0], fov: 40}\n" +
            kBall,
        "lint.yaml");
    EXPECT_TRUE(of_rule(lit, "no-lights").empty());
    Scene seen = lit;
    seen.settings.integrator = IntegratorKind::distributed;
    EXPECT_EQ(of_rule(seen, "no-lights").size(), 1u);
    Scene dark = lit;
    dark.settings.background = {};
    EXPECT_EQ(of_rule(dark, "no-lights").size(), 1u);
}

TEST(Lint, CameraInsideASphereWarnsAndOutsideDoesNot) {
    const auto warnings =
        of_rule(scene_with("objects: [{type: sphere, center: [0, 1, -5], radius: 0.5}]\n"),
                "camera-inside");
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(warnings[0].subject, "camera");
    EXPECT_NE(warnings[0].message.find("object 0 (sphere)"), std::string::npos);
    EXPECT_TRUE(of_rule(scene_with(kBall), "camera-inside").empty());
}

TEST(Lint, CameraInsideTheHollowOfADifferenceIsOutsideTheSolid) {
    const std::string hollow =
        "objects:\n"
        "  - type: difference\n"
        "    objects:\n"
        "      - {type: box, min: [-10, -10, -10], max: [10, 10, 10]}\n"
        "      - {type: sphere, center: [0, 0, 0], radius: 8}\n";
    EXPECT_TRUE(of_rule(scene_with(hollow), "camera-inside").empty());
}

TEST(Lint, PointLightInsideAShadowCastingBoxWarns) {
    const Scene boxed = scene_with(
        "objects: [{type: box, min: [-1, 4, -4], max: [1, 6, -2]}]\n");  // holds (0, 5, -3)
    const auto warnings = of_rule(boxed, "light-inside");
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(warnings[0].subject, "light 0 (point)");
    EXPECT_TRUE(of_rule(scene_with(kBall), "light-inside").empty());
}

TEST(Lint, ABoxThatCastsNoShadowLetsItsLightOut) {
    const Scene boxed = scene_with(
        "objects: [{type: box, min: [-1, 4, -4], max: [1, 6, -2], casts_shadow: false}]\n");
    EXPECT_TRUE(of_rule(boxed, "light-inside").empty());
}

TEST(Lint, SphereAreaLightInsideItsOwnFaceDoesNotWarn) {
    const Scene scene =
        scene_with(kBall, "lights: [{type: sphere, center: [0, 5, 0], radius: 0.5}]\n");
    EXPECT_TRUE(of_rule(scene, "light-inside").empty());
}

// The notes' k_local + k_refl + k_trans = 1: 0.7 + 0.2 + 0.3 + 0 = 1.2.
TEST(Lint, CoefficientsAboveOneMakeEnergy) {
    const Scene scene = scene_with(
        "materials: {shiny: {kd: 0.7, ks: 0.2, reflect: 0.3}}\n"
        "objects: [{type: sphere, center: [0, 0, 0], radius: 1, "
        "material: shiny}]\n");
    const auto warnings = of_rule(scene, "energy");
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(warnings[0].subject, "material \"shiny\"");
    EXPECT_NE(warnings[0].message.find("0.7 + 0.2 + 0.3 + 0 = 1.2"), std::string::npos)
        << warnings[0].message;
}

// For Whitted's tracer the rule is a guide (a note); the path tracer scales such a material
// down (a warning, saying by how much).
TEST(Lint, EnergyIsANoteForWhittedAndAWarningForThePathTracer) {
    const std::string shiny =
        "materials: {shiny: {kd: 0.7, ks: 0.2, reflect: 0.3}}\n"
        "objects: [{type: sphere, center: [0, 0, 0], radius: 1, material: shiny}]\n";
    EXPECT_TRUE(of_rule(scene_with(shiny), "energy").at(0).note);
    const auto path = of_rule(path_scene_with(shiny), "energy");
    ASSERT_EQ(path.size(), 1u);
    EXPECT_FALSE(path[0].note);
    EXPECT_NE(path[0].message.find("the path integrator scales the four down by 1/1.2"),
              std::string::npos)
        << path[0].message;
}

TEST(Lint, ThePathTracerNotesThatItLeavesTheAmbientTermOut) {
    const std::string lit =
        "ambient: [0.2, 0.2, 0.2]\nmaterials: {dull: {ka: 0.3}}\n"
        "objects: [{type: sphere, center: [0, 0, 0], radius: 1, "
        "material: dull}]\n";
    EXPECT_TRUE(of_rule(scene_with(lit), "ambient").empty());  // whitted uses it
    const auto notes = of_rule(path_scene_with(lit), "ambient");
    ASSERT_EQ(notes.size(), 1u);
    EXPECT_TRUE(notes[0].note);
    EXPECT_EQ(notes[0].subject, "material \"dull\"");
}

TEST(Lint, CoefficientsSummingToExactlyOneAreFine) {
    const Scene scene = scene_with(
        "materials: {glass: {kd: 0.1, ks: 0.2, reflect: 0.1, "
        "transmit: 0.6, ior: 1.5}}\n"
        "objects: [{type: sphere, center: [0, 0, 0], radius: 1, "
        "material: glass}]\n");
    EXPECT_TRUE(of_rule(scene, "energy").empty());
}

TEST(Lint, TransmissionWithoutAnIndexOfRefractionWarns) {
    const Scene scene = scene_with(
        "materials: {clear: {kd: 0.1, transmit: 0.8}}\n"
        "objects: [{type: sphere, center: [0, 0, 0], radius: 1, "
        "material: clear}]\n");
    const auto warnings = of_rule(scene, "ior");
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(warnings[0].subject, "material \"clear\"");
    const Scene glass = scene_with(
        "materials: {clear: {kd: 0.1, transmit: 0.8, ior: 1.5}}\n"
        "objects: [{type: sphere, center: [0, 0, 0], radius: 1, "
        "material: clear}]\n");
    EXPECT_TRUE(of_rule(glass, "ior").empty());
}

TEST(Lint, AMaterialNoObjectUsesWarns) {
    const Scene scene = scene_with(
        "materials: {used: {kd: 0.5}, spare: {kd: 0.5}}\n"
        "objects: [{type: sphere, center: [0, 0, 0], radius: 1, "
        "material: used}]\n");
    const auto warnings = of_rule(scene, "unused-material");
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(warnings[0].subject, "material \"spare\"");
    EXPECT_TRUE(of_rule(scene_with(kBall), "unused-material").empty());
}

TEST(Lint, ObjectsBehindOrBesideTheCameraAreOutOfView) {
    const Scene scene = scene_with(
        "objects:\n"
        "  - {type: sphere, center: [0, 0, 0], radius: 1}\n"           // in view
        "  - {type: sphere, center: [0, 1, -9], radius: 1}\n"          // behind the eye
        "  - {type: sphere, center: [30, 0, 0], radius: 1}\n"          // far to the side
        "  - {type: plane, point: [0, -1, 0], normal: [0, 1, 0]}\n");  // unbounded
    const auto warnings = of_rule(scene, "out-of-view");
    ASSERT_EQ(warnings.size(), 2u);
    EXPECT_EQ(warnings[0].subject, "object 1 (sphere)");
    EXPECT_EQ(warnings[1].subject, "object 2 (sphere)");
}

TEST(Lint, AnObjectAcrossTheEdgeOfTheViewIsInView) {
    // The view's half-width at z = 5 is 5 tan(20 deg) 4/3 = 2.43: a sphere at x = 3 of radius 1
    // reaches into it.
    const Scene scene = scene_with("objects: [{type: sphere, center: [3, 1, 0], radius: 1}]\n");
    EXPECT_TRUE(of_rule(scene, "out-of-view").empty());
}

// The YAML loader keeps where each material, light and object was read (1-based).
TEST(Lint, WarningsPointToTheLineOfTheirSubject) {
    const Scene scene = scene_with(
        "materials:\n"          // line 4
        "  used: {kd: 0.5}\n"   // line 5
        "  spare: {kd: 0.5}\n"  // line 6
        "objects:\n"            // line 7
        "  - {type: sphere, center: [0, 0, 0], radius: 1, material: used}\n"
        "  - {type: sphere, center: [0, 1, -9], radius: 1, material: used}\n");  // line 9
    const auto unused = of_rule(scene, "unused-material");
    ASSERT_EQ(unused.size(), 1u);
    ASSERT_TRUE(unused[0].location);
    EXPECT_EQ(unused[0].location->file, "lint.yaml");
    EXPECT_EQ(unused[0].location->line, 6);
    EXPECT_EQ(unused[0].location->column, 3);
    const auto behind = of_rule(scene, "out-of-view");
    ASSERT_EQ(behind.size(), 1u);
    ASSERT_TRUE(behind[0].location);
    EXPECT_EQ(behind[0].location->line, 9);
    EXPECT_EQ(behind[0].location->column, 5);
    EXPECT_FALSE(of_rule(scene_with(kBall, ""), "no-lights")[0].location);
}

// The image settings of some integrators warn, at their place, under the others.
TEST(Lint, PhotonsAndNextEventWarnUnderIntegratorsThatIgnoreThem) {
    const auto parse = [](const std::string& integrator, const std::string& settings) {
        return parse_yaml_scene("image: {integrator: " + integrator + ", " + settings + "}\n" +
                                    "camera: {from: [0, 1, -5], at: [0, 0, 0], fov: 40}\n"
                                    "lights: [{type: point, position: [0, 5, -3]}]\n" +
                                    kBall,
                                "lint.yaml");
    };
    const auto photons = of_rule(parse("path", "photons: {per_pass: 1000}"), "unused-setting");
    ASSERT_EQ(photons.size(), 1u);
    EXPECT_EQ(photons[0].subject, "image.photons");
    EXPECT_EQ(photons[0].message,
              "the path integrator sends no photons: image.photons is for integrator: photon");
    ASSERT_TRUE(photons[0].location);
    EXPECT_EQ(photons[0].location->line, 1);
    EXPECT_EQ(photons[0].location->column, 36);  // the value, after "photons: "
    const auto next_event = of_rule(parse("distributed", "next_event: all"), "unused-setting");
    ASSERT_EQ(next_event.size(), 1u);
    EXPECT_EQ(next_event[0].subject, "image.next_event");
    EXPECT_NE(next_event[0].message.find("samples every light"), std::string::npos);
    EXPECT_NE(of_rule(parse("light", "next_event: one"), "unused-setting")[0].message.find(
                  "samples no lights"),
              std::string::npos);
    // Where they act, nothing.
    EXPECT_TRUE(
        of_rule(parse("photon", "photons: {per_pass: 1000}, next_event: all"), "unused-setting")
            .empty());
    EXPECT_TRUE(of_rule(parse("path", "next_event: all"), "unused-setting").empty());
}

// Under the cone integrator, a note for each object it has no cone test for; none under others.
TEST(Lint, ConeFallbackNotesTheObjectsTheConeSeesByItsAxis) {
    const auto parse = [](const std::string& integrator) {
        return parse_yaml_scene("image: {integrator: " + integrator + "}\n" +
                                    "camera: {from: [0, 1, -5], at: [0, 0, 0], fov: 40}\n"
                                    "lights: [{type: point, position: [0, 5, -3]}]\n"
                                    "objects:\n"
                                    "  - {type: sphere, center: [0, 0, 0], radius: 1}\n"
                                    "  - {type: box, min: [1, 0, 0], max: [2, 1, 1]}\n",
                                "lint.yaml");
    };
    const auto notes = of_rule(parse("cone"), "cone-fallback");
    ASSERT_EQ(notes.size(), 1u);
    EXPECT_EQ(notes[0].subject, "object 1 (box)");
    EXPECT_TRUE(notes[0].note);
    ASSERT_TRUE(notes[0].location);
    EXPECT_EQ(notes[0].location->line, 6);
    EXPECT_TRUE(of_rule(parse("whitted"), "cone-fallback").empty());
}

}  // namespace
}  // namespace glint
