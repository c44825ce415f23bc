#include "glint/scene/scene_error.h"

#include <gtest/gtest.h>

namespace glint {
namespace {

TEST(SceneError, FormatsLikeACompilerWithGutterCaretAndNotes) {
    const SceneError error({"scenes/cornell.yaml", 14, 11}, "unknown object type \"spere\"",
                           {"object types are: box, plane, sphere, triangle (did you mean "
                            "\"sphere\"?)"},
                           "  - type: spere", 5);
    EXPECT_EQ(format_scene_error(error),
              "scenes/cornell.yaml:14:11: error: unknown object type \"spere\"\n"
              "   14 |   - type: spere\n"
              "      |           ^~~~~\n"
              "note: object types are: box, plane, sphere, triangle (did you mean "
              "\"sphere\"?)\n");
}

TEST(SceneError, WithoutALineThereIsNoExcerpt) {
    const SceneError error({"missing.yaml", 0, 0}, "cannot read scene file: No such file");
    EXPECT_EQ(format_scene_error(error),
              "missing.yaml: error: cannot read scene file: No such file\n");
}

TEST(SceneError, GutterGrowsWithTheLineNumber) {
    const SceneError error({"big.yaml", 123456, 1}, "duplicate key \"a\"", {}, "a: 1", 1);
    EXPECT_EQ(format_scene_error(error),
              "big.yaml:123456:1: error: duplicate key \"a\"\n"
              " 123456 | a: 1\n"
              "        | ^\n");
}

TEST(SceneError, CaretKeepsTabsAndStopsAtTheEndOfTheLine) {
    const SceneError error({"t.yaml", 2, 3}, "bad", {}, "\t x", 99);
    EXPECT_EQ(format_scene_error(error),
              "t.yaml:2:3: error: bad\n"
              "    2 | \t x\n"
              "      | \t ^\n");
}

TEST(SceneError, WhatIsTheMessage) {
    const SceneError error({"a.yaml", 1, 1}, "the message");
    EXPECT_STREQ(error.what(), "the message");
}

}  // namespace
}  // namespace glint
