// POV-Ray's radiosity onto glint's path tracer, and emission in a pigment's colours: which
// integrator and samples a radiosity scene takes, what becomes of the ambient term before and
// from POV-Ray 3.7, and the settings' checks.
#include "glint/scene/pov/pov_radiosity.h"

#include <gtest/gtest.h>

#include "glint/scene/pov/pov_scene.h"
#include "glint/scene/scene_error.h"

namespace glint::pov_radiosity_test {
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

bool any_warning_has(const Scene& s, const std::string& part) {
    for (const std::string& w : s.warnings)
        if (w.find(part) != std::string::npos) return true;
    return false;
}

const std::string kBall = "sphere { 0, 1 pigment { rgb <1, 0.5, 0.25> } finish { ambient 0.2 } }";

// From POV-Ray 3.7 radiosity replaces the ambient term: the path tracer computes the light it
// stood in for, and no surface glows.
TEST(PovRadiosity, RendersByThePathTracerWithoutTheAmbientTerm) {
    const Scene s = parse(
        "#version 3.7; global_settings { ambient_light 0.5 radiosity { "
        "count 100 error_bound 0.5 recursion_limit 2 } } " +
        kBall);
    EXPECT_EQ(s.settings.integrator, IntegratorKind::path);
    EXPECT_EQ(s.settings.samples_per_pixel, kPovRadiositySamples);
    EXPECT_EQ(s.ambient, Color{});
    ASSERT_EQ(s.materials.size(), 1u);
    EXPECT_EQ(s.materials[0].maps, nullptr);
    EXPECT_TRUE(s.warnings.empty());
}

// Before 3.7 POV-Ray adds the ambient term under radiosity too, and gathers it from the
// surfaces around: each glows with ka * ambient_light in its own colour.
TEST(PovRadiosity, OlderScenesGlowWithTheirAmbientTerm) {
    const Scene s =
        parse("#version 3.6; global_settings { ambient_light 0.5 radiosity { } } " + kBall);
    EXPECT_EQ(s.settings.integrator, IntegratorKind::path);
    EXPECT_EQ(s.ambient, Color{});
    ASSERT_NE(s.materials[0].maps, nullptr);
    EXPECT_EQ(s.materials[0].maps->color_emission, Color::gray(0.1f));
    EXPECT_TRUE(emits(s.materials[0]));
}

// Radiosity wherever global_settings is written, after the objects too; more samples asked
// for elsewhere (focal blur's) are kept.
TEST(PovRadiosity, KeepsMoreSamplesAndReadsSettingsAfterTheObjects) {
    const Scene s = parse(kBall +
                          " camera { location -5*z look_at 0 aperture 0.1 blur_samples 64 } "
                          "global_settings { radiosity { brightness 1 } }");
    EXPECT_EQ(s.settings.integrator, IntegratorKind::path);
    EXPECT_EQ(s.settings.samples_per_pixel, 64);
}

TEST(PovRadiosity, ReadsEverySettingOfPovRay37) {
    const Scene s = parse(
        "global_settings { radiosity { adc_bailout 0.01 always_sample off brightness 2 "
        "count 35, 1000 error_bound 1.8 gray_threshold 0 low_error_factor 0.5 max_sample -1 "
        "maximum_reuse 0.2 minimum_reuse 0.015 nearest_count 5, 3 normal on media off "
        "pretrace_start 0.08 pretrace_end 0.04 recursion_limit 3 subsurface off } } " +
        kBall);
    EXPECT_EQ(s.settings.integrator, IntegratorKind::path);
    // The brightness scales what is gathered, which a path tracer does not set apart.
    EXPECT_TRUE(any_warning_has(s, "brightness 2 is read past"));
}

// The path integrator does not march media: a scene with them keeps the integrator that does.
TEST(PovRadiosity, AScenesMediaKeepItsIntegrator) {
    const Scene s = parse(
        "global_settings { radiosity { } } "
        "sphere { 0, 1 pigment { rgbt 1 } hollow "
        "interior { media { absorption 0.5 } } }");
    EXPECT_EQ(s.settings.integrator, IntegratorKind::whitted);
    EXPECT_EQ(s.settings.samples_per_pixel, 1);
    EXPECT_TRUE(any_warning_has(s, "holds media"));
}

TEST(PovRadiosity, BadSettingsAreLocatedErrors) {
    EXPECT_EQ(error_of("global_settings { radiosity { pretrace_end 2 } }"),
              "scene.pov:1:44: error: pretrace_end must be in [0, 1], got 2\n"
              "    1 | global_settings { radiosity { pretrace_end 2 } }\n"
              "      |                                            ^\n");
    EXPECT_NE(error_of("global_settings { radiosity { count 0 } }").find("scene.pov:1:37"),
              std::string::npos);
    EXPECT_NE(error_of("global_settings { radiosity { recursion_limit 21 } }").find("1:47"),
              std::string::npos);
    EXPECT_NE(error_of("global_settings { radiosity { brightness -1 } }")
                  .find("brightness must be above 0, got -1"),
              std::string::npos);
    EXPECT_NE(error_of("global_settings { radiosity { error_bound -0.5 } }")
                  .find("error_bound must not be negative"),
              std::string::npos);
    EXPECT_NE(error_of("global_settings { radiosity { quality 3 } }")
                  .find("scene.pov:1:31: error: \"quality\" is not a radiosity setting"),
              std::string::npos);
}

// POV-Ray's emission gives off the pigment's own colour: a constant for a plain colour, the
// surface colour times it for a pattern.
TEST(PovRadiosity, EmissionFollowsThePigment) {
    const Scene plain = parse("sphere { 0, 1 pigment { rgb <1, 0.5, 0> } finish { emission 2 } }");
    EXPECT_EQ(plain.materials[0].emission, (Color{2, 1, 0}));
    EXPECT_EQ(plain.materials[0].maps, nullptr);
    const Scene pattern =
        parse("sphere { 0, 1 pigment { checker rgb 1 rgb 0 } finish { emission 0.5 diffuse 0 } }");
    EXPECT_EQ(pattern.materials[0].emission, Color{});
    ASSERT_NE(pattern.materials[0].maps, nullptr);
    EXPECT_EQ(pattern.materials[0].maps->color_emission, Color::gray(0.5f));
}

}  // namespace
}  // namespace glint::pov_radiosity_test
