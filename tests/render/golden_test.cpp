// Golden images: each example scene, rendered small, must match its reference image in
// tests/golden/ within a tolerance (float results may differ slightly across compilers).
// GLINT_UPDATE_GOLDEN=1 rewrites the references; look at every one before committing it.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "glint/image/compare.h"
#include "glint/image/image_io.h"
#include "glint/render/render.h"
#include "glint/scene/yaml/yaml_scene_loader.h"

namespace glint {
namespace {

namespace fs = std::filesystem;

constexpr int kWidth = 160;
constexpr int kHeight = 120;
// Silhouettes and shadow edges may flip a few pixels; anything more is a regression.
constexpr double kMaxRmse = 2.0 / 255;
constexpr double kPixelThreshold = 8.0 / 255;
constexpr double kMaxFractionOver = 0.01;

class GoldenImage : public ::testing::TestWithParam<std::string> {};

TEST_P(GoldenImage, MatchesTheReference) {
    const std::string name = GetParam();
    const fs::path source = GLINT_SOURCE_DIR;
    const fs::path golden = source / "tests/golden" / (fs::path(name).stem().string() + ".png");
    Scene scene = load_yaml_scene(source / "scenes" / name);
    scene.settings.width = kWidth;
    scene.settings.height = kHeight;
    const RenderResult result = render(World(scene), {});
    ASSERT_EQ(result.bad_samples.count, 0u);

    if (std::getenv("GLINT_UPDATE_GOLDEN")) {
        write_image(golden, result.image);
        GTEST_SKIP() << "wrote " << golden;
    }
    // Compare against what the PNG round trip gives, so quantisation is not counted as error.
    const fs::path out_dir = GLINT_TEST_OUTPUT_DIR;
    fs::create_directories(out_dir);
    const fs::path actual_file = out_dir / golden.filename();
    write_image(actual_file, result.image);
    const ImageDifference d =
        compare_images(read_image(actual_file), read_image(golden), kPixelThreshold);
    const bool ok = d.rmse <= kMaxRmse && d.fraction_over_threshold <= kMaxFractionOver;
    if (!ok) {
        write_image(out_dir / ("diff-" + golden.filename().string()),
                    difference_image(read_image(actual_file), read_image(golden)));
    }
    EXPECT_TRUE(ok) << name << ": " << describe(d) << "\n  rendered: " << actual_file
                    << "\n  expected: " << golden;
}

INSTANTIATE_TEST_SUITE_P(
    Scenes, GoldenImage,
    ::testing::Values("showcase.yaml", "whitted-basics.yaml", "features/highlights.yaml",
                      "features/shadows.yaml", "features/transparent-shadows.yaml",
                      "features/reflection.yaml", "features/refraction.yaml",
                      "features/textures.yaml", "features/attenuation.yaml",
                      "features/orthographic.yaml", "features/supersampling.yaml",
                      "features/csg.yaml", "features/quadrics.yaml", "features/polygons.yaml",
                      "features/implicit.yaml", "features/fractals.yaml", "features/meshes.yaml",
                      "features/model-formats.yaml", "features/gltf-ply-stl.yaml",
                      "features/instancing.yaml"),
    [](const ::testing::TestParamInfo<std::string>& param) {
        std::string id = fs::path(param.param).stem().string();
        for (char& c : id)
            if (c == '-') c = '_';
        return id;
    });

}  // namespace
}  // namespace glint
