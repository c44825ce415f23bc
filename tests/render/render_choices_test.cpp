// The acceleration structure and output variables a front end names: one check, one wording,
// for the command line, Python and the page.
#include "glint/render/render_choices.h"

#include <gtest/gtest.h>

#include <string>

#include "glint/scene/setting_overrides.h"

namespace glint {
namespace {

TEST(RenderChoices, AStructureByNameOrAnErrorListingTheNames) {
    EXPECT_EQ(accel_named("kdtree"), AccelKind::kdtree);
    EXPECT_EQ(accel_named("bvh"), AccelKind::bvh);
    try {
        accel_named("octree");
        FAIL() << "an unknown structure was taken";
    } catch (const SettingsError& e) {
        EXPECT_EQ(e.key(), "accel");
        EXPECT_STREQ(e.what(), "accel: unknown name \"octree\"");
        ASSERT_EQ(e.notes().size(), 1u);
        EXPECT_EQ(e.notes()[0].rfind("accel names are: bvh, grid, kdtree, list", 0), 0u);
    }
}

TEST(RenderChoices, OutputVariablesByNameAndGroupForAnIntegratorThatTracesRays) {
    const AovSet set = aovs_named("depth,ids", IntegratorKind::whitted);
    EXPECT_TRUE(set.has(Aov::depth));
    EXPECT_TRUE(set.has(Aov::object));
    EXPECT_TRUE(set.has(Aov::material));
    EXPECT_FALSE(set.has(Aov::normal));
    EXPECT_TRUE(aovs_named("all", IntegratorKind::path).has(Aov::indirect));
}

TEST(RenderChoices, OutputVariablesRefusedWithTheKeyNamed) {
    const auto refusal = [](const char* list, IntegratorKind integrator) {
        try {
            aovs_named(list, integrator);
        } catch (const SettingsError& e) {
            EXPECT_EQ(e.key(), "aovs");
            return std::string(e.what());
        }
        return std::string("taken");
    };
    EXPECT_EQ(refusal("depth,colour", IntegratorKind::whitted).rfind("aovs: unknown", 0), 0u)
        << refusal("depth,colour", IntegratorKind::whitted);
    EXPECT_EQ(refusal("depth", IntegratorKind::cone),
              "aovs: the output variables follow rays, and the cone integrator traces cones");
    EXPECT_EQ(aovs_problem({}, IntegratorKind::beam), std::nullopt);  // none asked: no problem
    EXPECT_EQ(*aovs_problem(aovs_named("depth", IntegratorKind::whitted), IntegratorKind::beam),
              "the output variables follow rays, and the beam integrator traces beams");
}

}  // namespace
}  // namespace glint
