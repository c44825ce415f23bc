// Malformed scenes in tests/scene/bad/, one file each, stating the error they must give (see
// bad_file_checks.h).
#include <gtest/gtest.h>

#include "bad_file_checks.h"
#include "glint/scene/integrator_fit.h"
#include "glint/scene/yaml/yaml_scene_loader.h"

namespace glint {
namespace {

const std::filesystem::path kBadDir = std::filesystem::path(GLINT_SOURCE_DIR) / "tests/scene/bad";

TEST(BadScenes, ThereAreAtLeast25) {
    EXPECT_GE(testing::files_with_extension(kBadDir, ".yaml").size(), 25u);
}

TEST(BadScenes, EachGivesItsStatedError) {
    for (const auto& file : testing::files_with_extension(kBadDir, ".yaml")) {
        // What the scene's integrator needs of it counts as the file's error too.
        testing::expect_stated_error(file, [&] { check_integrator_fits(load_yaml_scene(file)); });
    }
}

}  // namespace
}  // namespace glint
