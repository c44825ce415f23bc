// A POV-Ray scene rendered by glint against POV-Ray's own render of the same file
// (tests/data/pov): the images must agree to 30 dB PSNR, the bar for the scenes inside
// the subset. Both are unantialiased, so the edges of far checker squares differ by aliasing.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "glint/image/compare.h"
#include "glint/image/image_io.h"
#include "glint/render/render.h"
#include "glint/scene/load_scene.h"

namespace glint {
namespace {

namespace fs = std::filesystem;

class PovReference : public ::testing::TestWithParam<const char*> {};

TEST_P(PovReference, MatchesPovRaysRender) {
    const std::string name = GetParam();
    const fs::path folder = fs::path(GLINT_SOURCE_DIR) / "tests/data/pov";
    Scene scene = load_scene(folder / (name + ".pov"));
    scene.settings.width = 160;
    scene.settings.height = 120;
    const RenderResult result = render(World(scene), {});
    const fs::path out = fs::path(GLINT_TEST_OUTPUT_DIR) / ("pov-" + name + ".png");
    fs::create_directories(out.parent_path());
    write_image(out, result.image);
    const ImageDifference d =
        compare_images(read_image(out), read_image(folder / (name + "-povray.png")));
    const double psnr = 20 * std::log10(1 / d.rmse);
    EXPECT_GE(psnr, 30) << describe(d) << "\n  rendered: " << out;
}

INSTANTIATE_TEST_SUITE_P(Scenes, PovReference,
                         ::testing::Values("basics", "camera", "clip", "csg", "finishes", "fog",
                                           "inverse", "language", "lights", "mesh", "patterns",
                                           "polynomials", "prism", "refraction", "shapes", "sky",
                                           "text", "tiles", "lathe", "normals", "operands",
                                           "images", "mesh2", "heightfields", "maps", "isosurfaces",
                                           "layers", "fisheye", "glass", "reflections", "sweep",
                                           "media"));

}  // namespace
}  // namespace glint
