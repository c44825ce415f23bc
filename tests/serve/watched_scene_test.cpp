// The watched scene: a save is loaded at the look after the one that saw it, a broken one keeps
// the last good scene beside its error, a file caught emptied before it is written is not loaded
// as it was caught, and a save that lands while the scene loads is not lost.
#include "watched_scene.h"

#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

namespace glint::serve::watched_scene_test {
namespace {

namespace fs = std::filesystem;

// A scene `width` pixels wide, padded so that no two widths give files of the same size.
std::string scene_text(int width) {
    return "image: {width: " + std::to_string(width) +
           ", height: 8}\n"
           "camera: {from: [0, 0, -5], at: [0, 0, 0]}\n"
           "objects:\n  - {type: sphere, center: [0, 0, 0], radius: 1}\n# " +
           std::string(std::size_t(width), '.') + "\n";
}

void write_file(const fs::path& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

fs::path fresh_file(const std::string& name) {
    const fs::path folder = fs::path(GLINT_TEST_OUTPUT_DIR) / ("watched_" + name);
    fs::remove_all(folder);
    fs::create_directories(folder);
    return folder / "scene.yaml";
}

TEST(WatchedScene, ASaveIsLoadedAtTheLookAfterAndABrokenOneKeepsTheLastGoodScene) {
    const fs::path file = fresh_file("save");
    write_file(file, scene_text(16));
    WatchedScene watched(file, LoadOptions{});
    EXPECT_FALSE(watched.reload_if_changed());
    EXPECT_EQ(watched.current().generation, 0);

    write_file(file, scene_text(20));
    EXPECT_FALSE(watched.reload_if_changed());  // seen
    EXPECT_EQ(watched.current().generation, 0);
    EXPECT_TRUE(watched.reload_if_changed());  // unchanged since: loaded
    EXPECT_FALSE(watched.reload_if_changed());
    EXPECT_EQ(watched.current().generation, 1);
    EXPECT_EQ(watched.current().scene->settings.width, 20);
    EXPECT_TRUE(watched.current().error.empty());

    write_file(file, "image: {width: 0}\n");
    EXPECT_FALSE(watched.reload_if_changed());
    EXPECT_TRUE(watched.reload_if_changed());
    const WatchedScene::Loaded broken = watched.current();
    EXPECT_EQ(broken.scene->settings.width, 20);
    EXPECT_NE(broken.error.find("scene.yaml:1:"), std::string::npos) << broken.error;

    write_file(file, scene_text(24));
    EXPECT_FALSE(watched.reload_if_changed());
    EXPECT_TRUE(watched.reload_if_changed());
    EXPECT_EQ(watched.current().scene->settings.width, 24);
    EXPECT_TRUE(watched.current().error.empty());
}

TEST(WatchedScene, AFileCaughtEmptiedBeforeItIsWrittenIsNotLoadedEmpty) {
    // An editor's save as std::ofstream does it: the file is truncated, then written. A look
    // between the two sees an empty file; the next sees the new text, and the one after loads it.
    const fs::path file = fresh_file("truncated");
    write_file(file, scene_text(16));
    WatchedScene watched(file, LoadOptions{});
    write_file(file, "");
    EXPECT_FALSE(watched.reload_if_changed());
    write_file(file, scene_text(20));
    EXPECT_FALSE(watched.reload_if_changed());
    EXPECT_EQ(watched.current().generation, 0);
    EXPECT_TRUE(watched.current().error.empty());
    EXPECT_TRUE(watched.reload_if_changed());
    EXPECT_EQ(watched.current().generation, 1);
    EXPECT_EQ(watched.current().scene->settings.width, 20);
    EXPECT_TRUE(watched.current().error.empty()) << watched.current().error;
}

TEST(WatchedScene, ASaveWhileTheSceneLoadsIsLoadedAtTheNextLook) {
    // One thread saves the scene over and over while another looks as fast as it can, so that
    // saves land mid-load. Once the saves stop, looking until nothing changes must give the last.
    const fs::path file = fresh_file("race");
    write_file(file, scene_text(1));
    WatchedScene watched(file, LoadOptions{});
    for (int round = 0; round < 20; ++round) {
        std::atomic<bool> saving{true};
        std::thread looker([&] {
            while (saving) watched.reload_if_changed();
        });
        const int last = 2 + round * 50 + 49;
        for (int width = 2 + round * 50; width <= last; ++width) {
            write_file(file, scene_text(width));
            std::this_thread::sleep_for(std::chrono::microseconds(200 + 37 * (width % 7)));
        }
        saving = false;
        looker.join();
        // The first look may only see the last save; the second loads it, if it has not yet.
        for (int look = 0; look < 2; ++look) {
            while (watched.reload_if_changed()) {
            }
        }
        ASSERT_EQ(watched.current().scene->settings.width, last) << "round " << round;
    }
}

}  // namespace
}  // namespace glint::serve::watched_scene_test
