// A render in parts: N parts merged give the image, samples and ray counts of one render of the
// whole, bit for bit, for every integrator, split by tiles (adaptive sampling included) or by
// sample passes (within float rounding for the one-pixel box, whose sums are floats); and a
// split that cannot work is refused, saying why.
#include "glint/render/render_part.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "common/every_integrator.h"

namespace glint {
namespace {

using testing::every_integrator;
using testing::load_small;

RenderOptions options() { return testing::small_pieces(); }

// The parts rendered one after another, each into a state of its own, and merged.
RenderState render_in_parts(const World& world, int count, PartSplit split) {
    const RenderSettings& settings = world.settings();
    const int passes = pass_count(settings.samples_per_pixel, pass_size_of(settings, options()));
    std::vector<RenderState> parts;
    for (int index = 1; index <= count; ++index) {
        const RenderPart part{index, count, split};
        RenderState state = initial_state(settings, options());
        EXPECT_FALSE(part_refusal(part, settings, state).has_value()) << describe(part);
        start_part(state, part, passes);
        const std::vector<WorkPiece> work = part_work(state, part, passes);
        EXPECT_FALSE(work.empty());
        EXPECT_FALSE(part_done(state, part, passes));
        EXPECT_TRUE(render(world, options(), nullptr, &state, work).complete);
        EXPECT_TRUE(part_done(state, part, passes));
        parts.push_back(std::move(state));
    }
    return merge_parts(std::move(parts), split, options().tile_size);
}

using testing::same_bits;

TEST(RenderPart, TileQuartersMergeIntoTheWholeRenderBitForBit) {
    for (const auto& c : every_integrator()) {
        SCOPED_TRACE(c.name);
        const World world(c.scene);
        RenderState whole = initial_state(world.settings(), options());
        const RenderResult one = render(world, options(), nullptr, &whole);
        const RenderState merged = render_in_parts(world, 3, PartSplit::tiles);
        EXPECT_TRUE(same_bits(resolve_image(merged), one.image));
        EXPECT_EQ(merged.samples, whole.samples);
        EXPECT_EQ(merged.tile_passes, whole.tile_passes);
        EXPECT_EQ(merged.rays, whole.rays);
        EXPECT_EQ(merged.bad_samples.count, whole.bad_samples.count);
    }
}

TEST(RenderPart, SamplePassPartsMergeIntoTheWholeRender) {
    for (const auto& c : every_integrator()) {
        if (c.scene.settings.adaptive) continue;
        SCOPED_TRACE(c.name);
        const World world(c.scene);
        RenderState whole = initial_state(world.settings(), options());
        const RenderResult one = render(world, options(), nullptr, &whole);
        const RenderState merged = render_in_parts(world, 2, PartSplit::passes);
        EXPECT_EQ(merged.samples, whole.samples);
        EXPECT_EQ(merged.rays, whole.rays);
        const Image image = resolve_image(merged);
        if (!whole.film.one_pixel()) {
            EXPECT_TRUE(same_bits(image, one.image));  // integer sums
            continue;
        }
        // Float sums added part by part instead of sample by sample.
        for (std::size_t i = 0; i < image.pixels.size(); ++i)
            for (const auto channel : {&Color::r, &Color::g, &Color::b}) {
                const float want = one.image.pixels[i].*channel;
                ASSERT_NEAR(image.pixels[i].*channel, want, 1e-5f * std::max(1.0f, want)) << i;
            }
    }
}

TEST(RenderPart, ASplitThatCannotWorkIsRefusedSayingWhy) {
    Scene scene = load_small("distributed-showcase.yaml", 16, 16, 8);  // 4 tiles, 4 passes of 2
    const RenderState state = initial_state(scene.settings, options());
    const auto refusal = [&](RenderPart part) {
        return part_refusal(part, scene.settings, state).value_or("accepted");
    };
    EXPECT_EQ(refusal({1, 4, PartSplit::tiles}), "accepted");
    EXPECT_NE(refusal({1, 5, PartSplit::tiles}).find("4 tiles, too few for 5 parts"),
              std::string::npos);
    EXPECT_EQ(refusal({2, 4, PartSplit::passes}), "accepted");
    EXPECT_NE(refusal({1, 5, PartSplit::passes}).find("4 passes of 2 samples, too few"),
              std::string::npos);
    scene.settings.adaptive = AdaptiveSampling{0.05f, 4};
    EXPECT_NE(refusal({1, 2, PartSplit::passes}).find("split its render by tiles"),
              std::string::npos);
    EXPECT_EQ(refusal({1, 1, PartSplit::passes}), "accepted");  // the whole is no split
}

TEST(RenderPart, PartsAreReadAsIOverN) {
    EXPECT_EQ(parse_render_part("3/8", PartSplit::tiles), (RenderPart{3, 8, PartSplit::tiles}));
    EXPECT_EQ(parse_render_part("1/1", PartSplit::passes), (RenderPart{1, 1, PartSplit::passes}));
    for (const char* bad : {"", "3", "0/8", "9/8", "3/0", "-1/2", "1/2/3", "a/b", "1 /2", "2/",
                            "/2", "1/100001", "99999999999/1"})
        EXPECT_FALSE(parse_render_part(bad, PartSplit::tiles).has_value()) << bad;
    EXPECT_EQ(describe(RenderPart{3, 8, PartSplit::passes}), "part 3 of 8 (passes)");
}

TEST(RenderPart, SamplePassPartsTakeRunsOfPassesThatCoverTheRenderOnce) {
    Scene scene = load_small("distributed-showcase.yaml", 16, 16, 14);  // 7 passes of 2
    const int passes = 7;
    std::vector<int> taken(passes, 0);
    for (int index = 1; index <= 3; ++index) {
        const RenderPart part{index, 3, PartSplit::passes};
        RenderState state = initial_state(scene.settings, options());
        start_part(state, part, passes);
        for (const WorkPiece& piece : part_work(state, part, passes))
            if (piece.tile == 0) ++taken[std::size_t(piece.pass)];
    }
    EXPECT_EQ(taken, std::vector<int>(passes, 1));
}

}  // namespace
}  // namespace glint
