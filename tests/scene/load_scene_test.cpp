// Picking the loader by file type: every format glint reads loads through one call, and an
// unknown extension is a located error that lists the formats.
#include "glint/scene/load_scene.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "glint/scene/integrator_fit.h"
#include "glint/scene/scene_error.h"

namespace glint {
namespace {

const std::filesystem::path kSource = GLINT_SOURCE_DIR;

TEST(LoadScene, ReadsYamlScenes) {
    const Scene scene = load_scene(kSource / "scenes/whitted-basics.yaml");
    EXPECT_EQ(scene.objects.size(), 5u);
}

// Every example scene loads, fits the integrator it names, and has its row in scenes/README.md.
TEST(LoadScene, EveryExampleSceneLoadsAndIsListed) {
    std::ifstream readme(kSource / "scenes/README.md");
    std::stringstream listed;
    listed << readme.rdbuf();
    int scenes = 0;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(kSource / "scenes")) {
        const std::string extension = entry.path().extension().string();
        if (extension != ".yaml" && extension != ".nff") continue;
        const std::string name = entry.path().lexically_relative(kSource / "scenes").string();
        SCOPED_TRACE(name);
        ++scenes;
        EXPECT_NO_THROW(check_integrator_fits(load_scene(entry.path())));
        EXPECT_NE(listed.str().find("| `" + name + "` |"), std::string::npos);
    }
    EXPECT_GT(scenes, 30);
}

TEST(LoadScene, ReadsNffAndGzippedNff) {
    const Scene plain = load_scene(kSource / "tests/data/spd/jacks.nff");
    const Scene gzipped = load_scene(kSource / "tests/data/spd/jacks.nff.gz");
    EXPECT_FALSE(plain.objects.empty());
    EXPECT_EQ(plain.objects.size(), gzipped.objects.size());
}

TEST(LoadScene, ReadsModelFilesWhateverTheCaseOfTheExtension) {
    EXPECT_FALSE(load_scene(kSource / "tests/data/meshes/cube_ascii.ply").objects.empty());
    const auto upper = std::filesystem::path(GLINT_TEST_OUTPUT_DIR) / "TETRA.STL";
    std::filesystem::create_directories(upper.parent_path());
    std::filesystem::copy_file(kSource / "tests/data/meshes/tetra_ascii.stl", upper,
                               std::filesystem::copy_options::overwrite_existing);
    EXPECT_FALSE(load_scene(upper).objects.empty());
}

TEST(LoadScene, UnknownExtensionListsTheFormats) {
    try {
        load_scene("scene.xyz");
        FAIL() << "no error";
    } catch (const SceneError& e) {
        EXPECT_EQ(e.message(), "unknown scene format \".xyz\"");
        ASSERT_EQ(e.notes().size(), 1u);
        EXPECT_NE(e.notes()[0].find(".nff.gz"), std::string::npos);
    }
}

}  // namespace
}  // namespace glint
