// The overrides a front end gives: each value checked, a lone side keeping the aspect, and the
// settings' joint checks, whichever front end asks.
#include "glint/scene/setting_overrides.h"

#include <gtest/gtest.h>

namespace glint::setting_overrides_test {

RenderSettings scene_settings() {
    RenderSettings s;
    s.width = 800;
    s.height = 600;
    s.samples_per_pixel = 4;
    return s;
}

SettingsError error_of(const SettingOverrides& o) {
    RenderSettings s = scene_settings();
    try {
        apply_setting_overrides(o, s);
    } catch (const SettingsError& e) {
        return e;
    }
    ADD_FAILURE() << "no error";
    return SettingsError("", "");
}

TEST(SettingOverrides, ALoneWidthKeepsTheAspect) {
    RenderSettings s = scene_settings();
    apply_setting_overrides({.width = 320}, s);
    EXPECT_EQ(s.width, 320);
    EXPECT_EQ(s.height, 240);  // 320 * 600 / 800
    s = scene_settings();
    apply_setting_overrides({.height = 3}, s);
    EXPECT_EQ(s.width, 4);  // round(3 * 800 / 600)
    s = scene_settings();
    apply_setting_overrides({.width = 10, .height = 10}, s);
    EXPECT_EQ(s.width, 10);
    EXPECT_EQ(s.height, 10);
}

TEST(SettingOverrides, ReplacesWhatIsGivenAndNothingElse) {
    RenderSettings s = scene_settings();
    apply_setting_overrides(
        {.spp = 16, .max_depth = 3, .integrator = "distributed", .shadows = "map"}, s);
    EXPECT_EQ(s.samples_per_pixel, 16);
    EXPECT_EQ(s.max_depth, 3);
    EXPECT_EQ(s.integrator, IntegratorKind::distributed);
    EXPECT_EQ(s.shadows, ShadowMethod::map);
    EXPECT_EQ(s.width, 800);
    const RenderSettings before = scene_settings();
    s = before;
    apply_setting_overrides({}, s);
    EXPECT_EQ(s.width, before.width);
    EXPECT_EQ(s.samples_per_pixel, before.samples_per_pixel);
}

TEST(SettingOverrides, OutOfRangeNamesTheKey) {
    const SettingsError spp = error_of({.spp = 0});
    EXPECT_EQ(spp.key(), "spp");
    EXPECT_STREQ(spp.what(), "spp: expected a whole number from 1 to 16777216, got 0");
    EXPECT_EQ(error_of({.width = -3}).key(), "width");
    EXPECT_EQ(error_of({.height = 70000}).key(), "height");
    EXPECT_EQ(error_of({.max_depth = 2000}).key(), "max_depth");
}

TEST(SettingOverrides, UnknownNamesAreListedWithASuggestion) {
    const SettingsError e = error_of({.integrator = "pth"});
    EXPECT_EQ(e.key(), "integrator");
    EXPECT_STREQ(e.what(), "integrator: unknown name \"pth\"");
    ASSERT_EQ(e.notes().size(), 1u);
    EXPECT_NE(e.notes()[0].find("(did you mean \"path\"?)"), std::string::npos) << e.notes()[0];
    EXPECT_EQ(error_of({.sampler = "x"}).key(), "sampler");
    EXPECT_EQ(error_of({.filter = "x"}).key(), "filter");
    EXPECT_EQ(error_of({.shadows = "x"}).key(), "shadows");
}

TEST(SettingOverrides, TheSettingsAsAWholeAreCheckedAsAScenesAre) {
    // The regular sampler takes square counts only.
    const SettingsError e = error_of({.spp = 8, .sampler = "regular"});
    EXPECT_EQ(e.key(), "");
    EXPECT_NE(std::string(e.what()).find("8"), std::string::npos) << e.what();
    // A lone height within its range whose kept aspect makes the width too wide.
    EXPECT_EQ(error_of({.height = 65536}).key(), "");
}

}  // namespace glint::setting_overrides_test
