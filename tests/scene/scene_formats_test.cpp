// The formats' table: each extension finds its format in any case, a double extension its own,
// and the help's line lists them all.
#include "glint/scene/scene_formats.h"

#include <gtest/gtest.h>

namespace glint {
namespace {

TEST(SceneFormats, EachExtensionFindsItsFormatInAnyCase) {
    for (const SceneFormat& format : scene_formats())
        for (const std::string_view extension : format.extensions) {
            const std::string name = "scene" + std::string(extension);
            ASSERT_EQ(scene_format_of(name), &format) << name;
            std::string upper = name;
            for (char& c : upper) c = char(std::toupper(static_cast<unsigned char>(c)));
            EXPECT_EQ(scene_format_of("/some/folder/" + upper), &format) << upper;
        }
    EXPECT_EQ(scene_format_of("jacks.nff.gz")->name, "NFF");
    EXPECT_EQ(scene_format_of("model.GLB")->name, "model");
}

TEST(SceneFormats, UnknownNamesFindNone) {
    EXPECT_EQ(scene_format_of("scene.xyz"), nullptr);
    EXPECT_EQ(scene_format_of("scene.gz"), nullptr);
    EXPECT_EQ(scene_format_of("scene"), nullptr);
    EXPECT_EQ(scene_format_of(".yaml"), nullptr);  // a hidden file with no name before the dot
    EXPECT_EQ(scene_format_of("yaml"), nullptr);
}

TEST(SceneFormats, TheLineListsEveryExtension) {
    const std::string text = scene_formats_text();
    for (const SceneFormat& format : scene_formats())
        for (const std::string_view extension : format.extensions)
            EXPECT_NE(text.find(std::string(extension)), std::string::npos) << extension;
    EXPECT_EQ(text.find(".yaml, .yml (glint's format), .nff, .nff.gz"), 0u) << text;
}

}  // namespace
}  // namespace glint
