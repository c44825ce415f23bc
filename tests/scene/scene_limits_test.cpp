// What a scene may ask for (LoadOptions::limits, the tool's --max-pixels, --max-samples and
// --max-ray-depth): over a default limit, a YAML scene, an NFF view and a texture are refused at
// the value that asks, saying how to raise the limit, and load once it is raised.
#include "glint/scene/scene_limits.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "glint/image/image.h"
#include "glint/image/png_io.h"
#include "glint/scene/load_scene.h"
#include "glint/scene/scene_error.h"

namespace glint {
namespace {

namespace fs = std::filesystem;

class SceneLimitsTest : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::path(GLINT_TEST_OUTPUT_DIR) / "scene_limits" /
               ::testing::UnitTest::GetInstance()->current_test_info()->name();
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    fs::path write(const std::string& name, const std::string& text) const {
        std::ofstream(dir_ / name, std::ios::binary) << text;
        return dir_ / name;
    }
    // The error loading `file` under `limits` gives; fails the test when it loads.
    static SceneError load_error(const fs::path& file, const SceneLimits& limits = {}) {
        try {
            load_scene(file, {{}, {}, limits});
        } catch (const SceneError& e) {
            return e;
        }
        ADD_FAILURE() << file << " loaded";
        return SceneError({}, "");
    }
    static Scene load(const fs::path& file, const SceneLimits& limits) {
        return load_scene(file, {{}, {}, limits});
    }

    fs::path dir_;
};

bool has_note(const SceneError& e, const std::string& note) {
    for (const std::string& n : e.notes())
        if (n == note) return true;
    return false;
}

TEST_F(SceneLimitsTest, DefaultsAreDocumentedValuesBelowTheCeilings) {
    const SceneLimits limits;
    EXPECT_EQ(limits.image_pixels, 268435456);
    EXPECT_EQ(limits.samples_per_pixel, 65536);
    EXPECT_EQ(limits.max_depth, 64);
    EXPECT_EQ(kMaxRenderPixels, std::int64_t(kMaxImageSide) * kMaxImageSide);
    EXPECT_LT(limits.image_pixels, kMaxRenderPixels);
    EXPECT_LT(limits.samples_per_pixel, kMaxSamplesPerPixel);
    EXPECT_LT(limits.max_depth, kMaxDepth);
}

TEST_F(SceneLimitsTest, YamlImageSamplesAndDepthAreRefusedOverTheLimitAndLoadUnderARaisedOne) {
    const fs::path scene =
        write("s.yaml",
              "camera: {from: [0, 0, -5], at: [0, 0, 0]}\n"
              "image: {width: 20000, height: 20000, samples: 70000, sampler: jittered, "
              "max_depth: 100}\n");
    SceneLimits limits;
    SceneError e = load_error(scene, limits);
    EXPECT_EQ(e.message(),
              "image is too large: 20000 x 20000 pixels, more than the limit of 268435456");
    EXPECT_TRUE(has_note(e, "raise the limit with --max-pixels N"));
    limits.image_pixels = 400000000;
    e = load_error(scene, limits);
    EXPECT_EQ(e.location().line, 2);
    EXPECT_EQ(e.location().column, 47);
    EXPECT_EQ(e.message(), "samples 70000 is more than the limit of 65536");
    EXPECT_TRUE(has_note(e, "raise the limit with --max-samples N"));
    limits.samples_per_pixel = 70000;
    e = load_error(scene, limits);
    EXPECT_EQ(e.message(), "max_depth 100 is more than the limit of 64");
    EXPECT_TRUE(has_note(e, "raise the limit with --max-ray-depth N"));
    limits.max_depth = 100;
    const Scene loaded = load(scene, limits);
    EXPECT_EQ(loaded.settings.width, 20000);
    EXPECT_EQ(loaded.settings.samples_per_pixel, 70000);
    EXPECT_EQ(loaded.settings.max_depth, 100);
}

// A limit below a default bounds what the file asks, not the default it leaves alone.
TEST_F(SceneLimitsTest, ALowLimitLeavesTheDefaultsOfKeysNotGiven) {
    const fs::path scene = write("s.yaml", "camera: {from: [0, 0, -5], at: [0, 0, 0]}\n");
    SceneLimits limits;
    limits.max_depth = 2;
    EXPECT_EQ(load(scene, limits).settings.max_depth, 5);
    write("s.yaml", "camera: {from: [0, 0, -5], at: [0, 0, 0]}\nimage: {max_depth: 3}\n");
    EXPECT_EQ(load_error(scene, limits).message(), "max_depth 3 is more than the limit of 2");
}

TEST_F(SceneLimitsTest, NoLimitRaisesAValuePastItsCeiling) {
    const fs::path scene = write("s.yaml",
                                 "camera: {from: [0, 0, -5], at: [0, 0, 0]}\n"
                                 "image: {width: 8, max_depth: 2000}\n");
    SceneLimits limits;
    limits.max_depth = kMaxDepth;
    EXPECT_EQ(load_error(scene, limits).message(), "image max_depth must be in 1..1024, got 2000");
}

TEST_F(SceneLimitsTest, AnNffViewOverThePixelLimitIsRefusedAtItsResolution) {
    const fs::path scene = write("s.nff",
                                 "v\nfrom 0 0 -8\nat 0 0 0\nup 0 1 0\nangle 25\nhither 0.001\n"
                                 "resolution 20000 20000\nf 1 1 1 1 0 0 0 1\ns 0 0 0 1\n");
    const SceneError e = load_error(scene);
    EXPECT_EQ(e.location().line, 7);
    EXPECT_EQ(e.location().column, 18);
    EXPECT_EQ(e.message(),
              "the view's resolution 20000 x 20000 has more pixels than the limit of 268435456");
    EXPECT_TRUE(has_note(e, "raise the limit with --max-pixels N"));
    SceneLimits limits;
    limits.image_pixels = 400000000;
    EXPECT_EQ(load(scene, limits).settings.width, 20000);
}

TEST_F(SceneLimitsTest, ATextureOverThePixelLimitIsRefusedNamingIt) {
    write_png(dir_ / "tex.png", Image(40, 30));
    const fs::path scene =
        write("s.yaml",
              "camera: {from: [0, 0, -5], at: [0, 0, 0]}\n"
              "image: {width: 10, height: 10}\n"
              "materials:\n"
              "  a: {color: {type: image, file: tex.png}}\n"
              "objects: [{type: sphere, center: [0, 0, 0], radius: 1, material: a}]\n");
    SceneLimits limits;
    limits.image_pixels = 1000;
    const SceneError e = load_error(scene, limits);
    EXPECT_EQ(e.location().line, 4);
    EXPECT_NE(e.message().find("image size 40x30 is larger than glint accepts"), std::string::npos)
        << e.message();
    EXPECT_NE(e.message().find("1000 pixels in all"), std::string::npos) << e.message();
    limits.image_pixels = 1200;
    EXPECT_NO_THROW(load(scene, limits));
}

}  // namespace
}  // namespace glint
