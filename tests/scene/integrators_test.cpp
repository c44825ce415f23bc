// The integrators' table: every kind has one row, names are sorted and found again, defaults are
// what sampler_of and filter_of give, and docs/scene-format.md's table says what it says.
#include "glint/scene/integrators.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <span>
#include <sstream>
#include <string>

#include "glint/scene/scene.h"

namespace glint {
namespace {

TEST(Integrators, EveryKindHasOneRowAndItsNameFindsItAgain) {
    const auto infos = integrator_infos();
    for (const IntegratorInfo& info : infos) {
        EXPECT_EQ(integrator_info(info.kind).name, info.name);
        EXPECT_EQ(integrator_from_name(info.name), info.kind);
        EXPECT_EQ(std::count_if(infos.begin(), infos.end(),
                                [&](const IntegratorInfo& i) { return i.kind == info.kind; }),
                  1);
        EXPECT_TRUE(describe_problem(info.filter).empty()) << info.name;
    }
    EXPECT_TRUE(std::is_sorted(integrator_names().begin(), integrator_names().end()));
    EXPECT_EQ(integrator_names().size(), infos.size());
    EXPECT_FALSE(integrator_from_name("raytracer"));
}

TEST(Integrators, ASceneWithoutSamplerOrFilterTakesItsIntegrators) {
    for (const IntegratorInfo& info : integrator_infos()) {
        RenderSettings s;
        s.integrator = info.kind;
        EXPECT_EQ(sampler_of(s), info.sampler) << info.name;
        EXPECT_EQ(filter_of(s), info.filter) << info.name;
        s.adaptive = AdaptiveSampling{};
        EXPECT_EQ(sampler_of(s), SamplerKind::sobol) << info.name;
    }
    EXPECT_EQ(filter_of(RenderSettings{}), FilterSpec{});  // whitted's one-pixel box
}

// The name that `from_name` maps to `kind`.
template <class Kind, class FromName>
std::string name_of(Kind kind, std::span<const std::string_view> names, FromName from_name) {
    for (const std::string_view name : names)
        if (from_name(name) == kind) return std::string(name);
    return "?";
}

std::string describe_filter(const FilterSpec& f) {
    std::ostringstream s;
    s << "`" << name_of(f.kind, filter_names(), filter_from_name) << "`, radius " << f.radius;
    return s.str();
}

TEST(Integrators, TheDocsTableIsTheTable) {
    std::ifstream in(std::filesystem::path(GLINT_SOURCE_DIR) / "docs/scene-format.md");
    std::ostringstream text;
    text << in.rdbuf();
    const std::string doc = text.str();
    const std::size_t table = doc.find("| integrator | sampler | filter | what it computes |");
    ASSERT_NE(table, std::string::npos);
    std::string expected =
        "| integrator | sampler | filter | what it computes |\n|---|---|---|---|\n";
    for (const IntegratorInfo& info : integrator_infos())
        expected += "| `" + std::string(info.name) + "` | `" +
                    name_of(info.sampler, sampler_names(), sampler_from_name) + "` | " +
                    describe_filter(info.filter) + " | " + std::string(info.summary) + " |\n";
    EXPECT_EQ(doc.substr(table, expected.size()), expected);
}

}  // namespace
}  // namespace glint
