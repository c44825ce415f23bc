#include "glint/scene/suggest.h"

#include <gtest/gtest.h>

#include <string_view>

namespace glint {
namespace {

constexpr std::string_view kTypes[] = {"box", "plane", "sphere", "triangle"};

TEST(Suggest, EditDistanceCountsInsertionsDeletionsSubstitutionsAndSwaps) {
    EXPECT_EQ(edit_distance("", ""), 0);
    EXPECT_EQ(edit_distance("", "abc"), 3);
    EXPECT_EQ(edit_distance("spere", "sphere"), 1);    // insertion
    EXPECT_EQ(edit_distance("radious", "radius"), 1);  // deletion
    EXPECT_EQ(edit_distance("bax", "box"), 1);         // substitution
    EXPECT_EQ(edit_distance("rde", "red"), 1);         // swap of neighbours
    EXPECT_EQ(edit_distance("kitten", "sitting"), 3);
}

TEST(Suggest, EditDistanceIgnoresCase) { EXPECT_EQ(edit_distance("Sphere", "sPHERE"), 0); }

TEST(Suggest, SuggestsTheNearestPlausibleName) {
    EXPECT_EQ(suggest_name("spere", kTypes), "sphere");
    EXPECT_EQ(suggest_name("Sphere", kTypes), "sphere");
    EXPECT_EQ(suggest_name("triangel", kTypes), "triangle");
    EXPECT_EQ(suggest_name("plan", kTypes), "plane");
}

TEST(Suggest, SuggestsNothingForUnrelatedNames) {
    EXPECT_FALSE(suggest_name("torus", kTypes));
    EXPECT_FALSE(suggest_name("", kTypes));
    EXPECT_FALSE(suggest_name("x", kTypes));
    EXPECT_FALSE(suggest_name(std::string(1000, 's'), kTypes));
}

TEST(Suggest, DidYouMeanIsAParentheticalOrNothing) {
    EXPECT_EQ(did_you_mean("spere", kTypes), " (did you mean \"sphere\"?)");
    EXPECT_EQ(did_you_mean("torus", kTypes), "");
}

}  // namespace
}  // namespace glint
