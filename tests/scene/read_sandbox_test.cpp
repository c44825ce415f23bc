// The sandbox's decision on its own: where a path leads, whether it lies inside a folder
// (component by component), the folders a scene may read, and the text of a refusal.
#include "glint/scene/read_sandbox.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "glint/scene/scene_error.h"

namespace glint {
namespace {

namespace fs = std::filesystem;

// A fresh folder for the test, resolved (the output folder may itself be under a link).
fs::path test_dir() {
    const fs::path dir = fs::path(GLINT_TEST_OUTPUT_DIR) / "read_sandbox" /
                         ::testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::remove_all(dir);
    fs::create_directories(dir);
    return fs::canonical(dir);
}

TEST(ReadSandbox, InsideComparesWholeComponentsNotStrings) {
    EXPECT_FALSE(is_inside("/a/bc", "/a/b"));
    EXPECT_FALSE(is_inside("/a/bc/d", "/a/b"));
    EXPECT_FALSE(is_inside("/a", "/a/b"));
    EXPECT_FALSE(is_inside("/b/a", "/a"));
    EXPECT_TRUE(is_inside("/a/b", "/a/b"));
    EXPECT_TRUE(is_inside("/a/b/c", "/a/b"));
    EXPECT_TRUE(is_inside("/a/b/c", "/a/b/"));
    EXPECT_TRUE(is_inside("/etc/passwd", "/"));
}

TEST(ReadSandbox, ResolvingFollowsDotDotAndSymbolicLinks) {
    const fs::path dir = test_dir();
    fs::create_directories(dir / "in" / "sub");
    fs::create_directories(dir / "out");
    fs::create_directory_symlink("../out", dir / "in" / "link");
    EXPECT_EQ(resolve_path(dir / "in" / "sub" / ".." / "x.png"), dir / "in" / "x.png");
    EXPECT_EQ(resolve_path(dir / "in" / "link" / "x.png"), dir / "out" / "x.png");
    // The part that does not exist is resolved as written.
    EXPECT_EQ(resolve_path(dir / "in" / "no" / ".." / ".." / "out" / "y"), dir / "out" / "y");
    // A relative path becomes absolute.
    EXPECT_TRUE(resolve_path("relative/x.png")->is_absolute());
}

TEST(ReadSandbox, TheSceneFolderAndTheAllowedOnesAreResolved) {
    const fs::path dir = test_dir();
    fs::create_directories(dir / "scene");
    fs::create_directories(dir / "models");
    fs::create_directory_symlink("models", dir / "models-link");
    const fs::path allowed[] = {dir / "scene" / ".." / "models-link"};
    const ReadSandbox sandbox = make_read_sandbox(dir / "scene" / "s.yaml", allowed);
    ASSERT_EQ(sandbox.folders.size(), 2u);
    EXPECT_EQ(sandbox.folders[0], dir / "scene");
    EXPECT_EQ(sandbox.folders[1], dir / "models");
    EXPECT_TRUE(may_read(sandbox, dir / "models" / "a.obj"));
    EXPECT_TRUE(may_read(sandbox, dir / "scene" / "deep" / "er" / "a.obj"));
    EXPECT_FALSE(may_read(sandbox, dir / "a.obj"));
    EXPECT_FALSE(may_read(sandbox, dir / "scene-other" / "a.obj"));
}

TEST(ReadSandbox, AFileNameWithoutAFolderHasTheCurrentFolder) {
    const ReadSandbox sandbox = make_read_sandbox("scene.yaml");
    ASSERT_EQ(sandbox.folders.size(), 1u);
    EXPECT_EQ(sandbox.folders[0], fs::canonical(fs::current_path()));
}

TEST(ReadSandbox, AnAllowedFolderMustExistAndBeAFolder) {
    const fs::path dir = test_dir();
    std::ofstream(dir / "file.txt") << "x";
    for (const auto& [folder, message] :
         {std::pair{dir / "nowhere", "the folder allowed to be read does not exist"},
          std::pair{dir / "file.txt", "the folder allowed to be read is not a folder"}}) {
        const fs::path allowed[] = {folder};
        try {
            make_read_sandbox(dir / "s.yaml", allowed);
            ADD_FAILURE() << "no error for " << folder;
        } catch (const SceneError& e) {
            EXPECT_EQ(e.location().file, folder.string());
            EXPECT_EQ(e.message(), message);
        }
    }
}

TEST(ReadSandbox, ARefusalNamesThePathAsWrittenWhereItLeadsAndTheWayOut) {
    const fs::path dir = test_dir();
    fs::create_directories(dir / "scene");
    const ReadSandbox sandbox = make_read_sandbox(dir / "scene" / "s.yaml");
    EXPECT_FALSE(check_read(sandbox, dir / "scene" / "sub" / "t.png", "texture", "sub/t.png"));
    const std::string written = "../../a/very/long/path/that/is/not/cut/short/when/quoted.png";
    const auto refusal = check_read(sandbox, dir / "scene" / written, "texture", written);
    ASSERT_TRUE(refusal);
    EXPECT_EQ(refusal->message,
              "texture \"" + written + "\" is outside the folders the scene may read");
    ASSERT_EQ(refusal->notes.size(), 3u);
    EXPECT_EQ(refusal->notes[0],
              "it resolves to " +
                  (dir.parent_path() / "a/very/long/path/that/is/not/cut/short/when/quoted.png")
                      .string());
    EXPECT_EQ(refusal->notes[1], "the scene may read files under " + (dir / "scene").string());
    EXPECT_EQ(refusal->notes[2], "allow the folder with --allow-read DIR");
}

}  // namespace
}  // namespace glint
