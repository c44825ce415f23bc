// Malformed POV-Ray scenes in tests/scene/bad_pov/, one file each, stating the error they must
// give in their first line (`// error: LINE:COL: MESSAGE`, see bad_file_checks.h).
#include <gtest/gtest.h>

#include "../bad_file_checks.h"
#include "glint/scene/load_scene.h"

namespace glint {
namespace {

const std::filesystem::path kBadDir =
    std::filesystem::path(GLINT_SOURCE_DIR) / "tests/scene/bad_pov";

TEST(BadPovScenes, ThereAreAtLeast20) {
    EXPECT_GE(testing::files_with_extension(kBadDir, ".pov").size(), 20u);
}

TEST(BadPovScenes, EachGivesItsStatedError) {
    for (const auto& file : testing::files_with_extension(kBadDir, ".pov"))
        testing::expect_stated_error(
            file, [&] { load_scene(file); }, "//");
}

}  // namespace
}  // namespace glint
