// The limit on the size of the files a scene reads: each kind's own by default, one limit for
// every kind with LoadOptions::max_file_bytes (`--max-file-size`): a scene file, a mesh, an OBJ's
// material library, a texture and an NFF file over it are refused, naming the file and how to
// raise the limit, and load once it is raised.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "glint/scene/load_scene.h"
#include "glint/scene/read_sandbox.h"
#include "glint/scene/scene_error.h"

namespace glint {
namespace {

namespace fs = std::filesystem;

const fs::path kFeatures = fs::path(GLINT_SOURCE_DIR) / "scenes/features";

// The error loading `file` under a limit of max_bytes gives; fails the test when it loads.
SceneError load_error(const fs::path& file, std::uintmax_t max_bytes) {
    try {
        load_scene(file, {{}, max_bytes});
    } catch (const SceneError& e) {
        return e;
    }
    ADD_FAILURE() << file << " loaded under a limit of " << max_bytes << " bytes";
    return SceneError({}, "");
}

bool has_raise_note(const SceneError& e) {
    for (const std::string& note : e.notes())
        if (note == kRaiseFileLimitNote) return true;
    return false;
}

TEST(FileSizeLimit, DescribedInMebibytesWhenWhole) {
    EXPECT_EQ(describe_file_limit(std::uintmax_t(64) << 20), "64 MiB");
    EXPECT_EQ(describe_file_limit(4096), "4096 bytes");
    ReadSandbox sandbox;
    EXPECT_EQ(sandbox.file_limit(123), 123u);
    sandbox.max_file_bytes = 7;
    EXPECT_EQ(sandbox.file_limit(123), 7u);
}

TEST(FileSizeLimit, TheSceneFileItself) {
    const fs::path scene = kFeatures / "shadows.yaml";
    const SceneError e = load_error(scene, 100);
    EXPECT_EQ(e.location().file, scene.string());
    EXPECT_EQ(e.message(), "scene file is larger than the limit of 100 bytes");
    EXPECT_TRUE(has_raise_note(e));
    EXPECT_NO_THROW(load_scene(scene, {{}, fs::file_size(scene)}));

    const fs::path nff = kFeatures / "jacks.nff";
    EXPECT_NE(load_error(nff, 100).message().find("larger than the limit of 100 bytes"),
              std::string::npos);
    EXPECT_NO_THROW(load_scene(nff, {{}, fs::file_size(nff)}));
}

TEST(FileSizeLimit, MeshesTheirMaterialLibrariesAndTextures) {
    const fs::path scene = kFeatures / "meshes.yaml";
    const std::uintmax_t yaml = fs::file_size(scene);
    const fs::path obj = kFeatures / "models/spot.obj";
    const fs::path png = kFeatures / "models/spot_texture.png";
    ASSERT_LT(yaml, fs::file_size(png));
    ASSERT_LT(fs::file_size(png), fs::file_size(obj));

    // Enough for the scene file, not for the mesh.
    const SceneError mesh = load_error(scene, fs::file_size(png));
    EXPECT_EQ(mesh.location().file, obj.string()) << format_scene_error(mesh);
    EXPECT_NE(mesh.message().find("more than the limit of " + std::to_string(fs::file_size(png)) +
                                  " bytes"),
              std::string::npos)
        << mesh.message();
    EXPECT_TRUE(has_raise_note(mesh));

    // Every file of the scene fits under the largest.
    std::uintmax_t largest = 0;
    for (const fs::directory_entry& e : fs::directory_iterator(kFeatures / "models"))
        largest = std::max(largest, e.file_size());
    EXPECT_NO_THROW(load_scene(scene, {{}, largest}));
}

TEST(FileSizeLimit, AnImageTexture) {
    const fs::path dir = fs::path(GLINT_TEST_OUTPUT_DIR) / "texture_limit";
    fs::remove_all(dir);
    fs::create_directories(dir);
    fs::copy_file(kFeatures / "models/spot_texture.png", dir / "spot.png");
    const fs::path scene = dir / "scene.yaml";
    std::ofstream(scene) << "camera: {from: [0, 0, 5], at: [0, 0, 0], fov: 40}\n"
                            "materials:\n"
                            "  cow: {color: {type: image, file: spot.png}}\n"
                            "objects:\n"
                            "  - {type: sphere, center: [0, 0, 0], radius: 1, material: cow}\n";
    const std::uintmax_t limit = 4096;
    const SceneError e = load_error(scene, limit);
    EXPECT_EQ(e.location().line, 3) << format_scene_error(e);
    EXPECT_NE(e.message().find("more than the limit of 4096"), std::string::npos) << e.message();
    EXPECT_NO_THROW(load_scene(scene, {{}, fs::file_size(dir / "spot.png")}));
}

}  // namespace
}  // namespace glint
