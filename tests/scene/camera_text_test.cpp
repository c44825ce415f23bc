// A camera as text: read as a scene file's camera is, errors at their place in the text, and
// written so that reading it back gives the same floats.
#include "glint/scene/camera_text.h"

#include <gtest/gtest.h>

#include <string>

#include "glint/scene/load_scene.h"
#include "glint/scene/scene_error.h"

namespace glint {
namespace {

void expect_same_view(const CameraSpec& a, const CameraSpec& b) {
    EXPECT_EQ(a.projection, b.projection);
    EXPECT_EQ(to_vector(a.from), to_vector(b.from));
    EXPECT_EQ(to_vector(a.at), to_vector(b.at));
    EXPECT_EQ(a.up, b.up);
    // Each projection keeps only its own parameters.
    if (a.projection != Projection::orthographic) {
        EXPECT_EQ(a.fov, b.fov);
    }
    if (a.projection == Projection::orthographic || a.projection == Projection::cylindrical) {
        EXPECT_EQ(a.height, b.height);
    }
}

TEST(CameraText, TheShowcasesCameraWrittenAndReadBackIsTheSame) {
    const Scene scene = load_scene(std::string(GLINT_SOURCE_DIR) + "/scenes/showcase.yaml");
    const std::string text = camera_yaml(scene.camera);
    EXPECT_EQ(text, "{from: [0, 2.2, -8], at: [0, 1, 0], up: [0, 1, 0], fov: 38}");
    expect_same_view(parse_camera_text(text, "page"), scene.camera);
}

TEST(CameraText, EveryFloatSurvivesTheTripAndEachProjectionWritesItsOwnKeys) {
    CameraSpec camera;
    camera.from = {0.1f, -1.0f / 3, 1e-7f};
    camera.at = {2.5f, 1.0f / 7, -3e5f};
    camera.up = {0.0f, 0.6f, 0.8f};
    camera.fov = 37.123457f;
    expect_same_view(parse_camera_text(camera_yaml(camera), "page"), camera);
    camera.projection = Projection::orthographic;
    camera.height = 3.75f;
    const std::string ortho = camera_yaml(camera);
    EXPECT_NE(ortho.find("type: orthographic"), std::string::npos);
    EXPECT_EQ(ortho.find("fov"), std::string::npos);
    expect_same_view(parse_camera_text(ortho, "page"), camera);
    camera.projection = Projection::cylindrical;
    camera.fov = 200;
    camera.cylinder_axis_across = true;
    const CameraSpec cylinder = parse_camera_text(camera_yaml(camera), "page");
    expect_same_view(cylinder, camera);
    EXPECT_TRUE(cylinder.cylinder_axis_across);
}

TEST(CameraText, JsonIsReadToo) {
    const CameraSpec camera = parse_camera_text(
        R"({"from": [1, 2, 3], "at": [0, 0, 0], "up": [0, 1, 0], "fov": 50})", "page");
    EXPECT_EQ(to_vector(camera.from), Vector3(1, 2, 3));
    EXPECT_EQ(camera.fov, 50);
}

std::string error_of(const std::string& text) {
    try {
        parse_camera_text(text, "page");
    } catch (const SceneError& e) {
        return format_scene_error(e);
    }
    return "no error";
}

TEST(CameraText, ABadCameraIsRefusedAtItsPlaceAsInAScene) {
    EXPECT_EQ(error_of("{from: [1, 1, 1], at: [1, 1, 1], up: [0, 1, 0]}")
                  .rfind("page:1:23: error: camera from and at must differ", 0),
              0u)
        << error_of("{from: [1, 1, 1], at: [1, 1, 1], up: [0, 1, 0]}");
    EXPECT_NE(error_of("{from: [0, 0, 0], at: [0, 0, 1], fov: 180}").find("fov"),
              std::string::npos);
    EXPECT_NE(error_of("{from: [0, 0, 0], at: [0, 0, 1], zoom: 2}").find("zoom"),
              std::string::npos);
    EXPECT_NE(error_of("{from: [0, 0, 0], at: [0, 0, 1], up: [0, 0, 2]}").find("parallel"),
              std::string::npos);
    EXPECT_NE(error_of("{from: [0, 0, 0], at: [0, 0").find("page:1:"), std::string::npos);
    EXPECT_NE(error_of("").find("page"), std::string::npos);
    EXPECT_NE(error_of(std::string(5000, '[')).find("nesting"), std::string::npos);
}

}  // namespace
}  // namespace glint
