// A state sent as bytes halfway through a render continues, on the other side, to the image,
// output variables and counts of the render that was never sent, bit for bit, for every
// integrator; bytes of another render are refused.
#include "glint/render/state_transfer.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "common/every_integrator.h"
#include "glint/render/render.h"
#include "glint/render/state_sums.h"

namespace glint {
namespace {

std::string bytes_of(const RenderState& state, int tile_size) {
    ByteWriter out;
    write_state(out, state, tile_size);
    return std::move(out.bytes());
}

ByteReader<> reader(const std::string& bytes) {
    return ByteReader<>(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(),
                        "a state cut short");
}

TEST(StateTransfer, AStateSentHalfwayContinuesToTheUnsentRender) {
    for (testing::IntegratorCase& c : testing::every_integrator()) {
        SCOPED_TRACE(c.name);
        c.scene.settings.filter = FilterSpec{FilterKind::gaussian, 2.0f};
        const World world(c.scene);
        RenderOptions o = testing::small_pieces(2);
        if (traces_rays(c.scene.settings.integrator)) o.aovs = parse_aov_list("depth,object");
        const RenderResult whole = render(world, o);

        RenderState sent = initial_state(world.settings(), o);
        const int passes = pass_count(world.settings().samples_per_pixel, sent.pass_size);
        const std::vector<WorkPiece> all = remaining_work(sent, passes);
        // The first pass and a half of the second: tiles at different passes.
        const std::size_t tiles = sent.tile_passes.size();
        const std::vector<WorkPiece> first(all.begin(), all.begin() + long(tiles + tiles / 2));
        render(world, o, nullptr, &sent, first);
        const std::string bytes = bytes_of(sent, o.tile_size);

        RenderState received = initial_state(world.settings(), o);
        ByteReader<> in = reader(bytes);
        read_state(in, received, o.tile_size);
        EXPECT_EQ(in.left(), 0u);
        EXPECT_EQ(received.tile_passes, sent.tile_passes);
        EXPECT_EQ(received.seconds, sent.seconds);
        EXPECT_TRUE(
            testing::same_bits(render_result(received, o).image, render_result(sent, o).image));
        const RenderResult continued = render(world, o, nullptr, &received);
        EXPECT_TRUE(testing::same_bits(continued.image, whole.image));
        EXPECT_TRUE(testing::same_bits(continued.samples_taken, whole.samples_taken));
        EXPECT_EQ(continued.rays.total(), whole.rays.total());
        ASSERT_EQ(continued.aovs.size(), whole.aovs.size());
        for (std::size_t i = 0; i < whole.aovs.size(); ++i)
            EXPECT_TRUE(testing::same_bits(continued.aovs[i].image, whole.aovs[i].image)) << i;
    }
}

// A film of more sums than are copied at a time arrives whole, each sum in its place.
TEST(StateTransfer, ALargeFilmsSumsArriveInTheirPlaces) {
    Scene scene = testing::load_small("showcase.yaml", 700, 500, 1);
    scene.settings.filter = FilterSpec{FilterKind::gaussian, 2.0f};
    const RenderOptions o = testing::small_pieces();
    RenderState sent = initial_state(scene.settings, o);
    const std::size_t n = sum_count(sent);
    ASSERT_GT(n, std::size_t(1) << 20);
    std::vector<FixedSum> sums(n);
    for (std::size_t i = 0; i < n; ++i) sums[i] = FixedSum(i) * 3 - 7;
    write_sums(sent, 0, sums);
    const std::string bytes = bytes_of(sent, o.tile_size);
    RenderState received = initial_state(scene.settings, o);
    ByteReader<> in = reader(bytes);
    read_state(in, received, o.tile_size);
    std::vector<FixedSum> back(n);
    copy_sums(received, 0, back);
    EXPECT_TRUE(back == sums);
}

TEST(StateTransfer, BytesOfAnotherRenderAreRefused) {
    const Scene scene = testing::load_small("showcase.yaml", 20, 12, 4);
    const World world(scene);
    const RenderOptions o = testing::small_pieces();
    const RenderState state = initial_state(world.settings(), o);
    const std::string bytes = bytes_of(state, o.tile_size);

    RenderState other_tiles = initial_state(world.settings(), o);
    ByteReader<> in = reader(bytes);
    EXPECT_THROW(read_state(in, other_tiles, 4), std::runtime_error);

    RenderOptions with_aovs = o;
    with_aovs.aovs = parse_aov_list("depth");
    RenderState other_films = initial_state(world.settings(), with_aovs);
    ByteReader<> again = reader(bytes);
    EXPECT_THROW(read_state(again, other_films, o.tile_size), std::runtime_error);

    const std::string cut = bytes.substr(0, bytes.size() / 2);
    RenderState short_of = initial_state(world.settings(), o);
    ByteReader<> short_in = reader(cut);
    EXPECT_THROW(read_state(short_in, short_of, o.tile_size), std::runtime_error);
}

}  // namespace
}  // namespace glint
