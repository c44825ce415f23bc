// A tile's carry holds exactly its own pixels' per-pixel state, survives bytes exactly, and a
// carry of the wrong shape is refused.
#include "glint/render/tile_carry.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "common/every_integrator.h"
#include "glint/render/render.h"

namespace glint {
namespace {

TEST(TileCarry, HoldsItsPixelsStateAndSurvivesBytesExactly) {
    Scene scene = testing::load_small("distributed-showcase.yaml", 20, 12, 8);
    scene.settings.adaptive = AdaptiveSampling{0.05f, 4};
    scene.settings.filter = FilterSpec{FilterKind::box};
    RenderOptions o;
    o.tile_size = 8;
    o.aovs = parse_aov_list("object,depth");
    const World world(scene);
    RenderState state = initial_state(world.settings(), o);
    render(world, o, nullptr, &state);
    const std::vector<Tile> tiles = make_tiles(20, 12, 8);
    const Tile& edge = tiles[2];  // x 16..20, y 0..8: 4 x 8 pixels
    const TileCarry carry = take_carry(state, edge, 2);
    EXPECT_EQ(carry.samples.size(), 32u);
    EXPECT_EQ(carry.errors.size(), 32u);
    EXPECT_EQ(carry.objects.size(), 32u);
    EXPECT_TRUE(carry.materials.empty());
    // Adaptive sampling's film and the depth's: both one pixel a sample.
    EXPECT_EQ(carry.box_sums.size(), 64u);
    EXPECT_EQ(carry.samples[5], state.samples[std::size_t(0) * 20 + 16 + 5 % 4 + 20 * (5 / 4)]);

    ByteWriter out;
    write_carry(out, carry);
    ByteReader<> in(reinterpret_cast<const unsigned char*>(out.bytes().data()), out.bytes().size(),
                    "short");
    RenderState other = initial_state(world.settings(), o);
    put_carry(other, edge, read_carry(in, other, edge));
    EXPECT_EQ(in.left(), 0u);
    const TileCarry back = take_carry(other, edge, 2);
    EXPECT_EQ(back.samples, carry.samples);
    EXPECT_EQ(back.objects, carry.objects);
    for (std::size_t i = 0; i < carry.box_sums.size(); ++i) {
        EXPECT_EQ(back.box_sums[i].sum, carry.box_sums[i].sum);
        EXPECT_EQ(back.box_sums[i].weight, carry.box_sums[i].weight);
    }
    for (std::size_t i = 0; i < carry.errors.size(); ++i) {
        EXPECT_EQ(back.errors[i].n, carry.errors[i].n);
        EXPECT_EQ(back.errors[i].m2, carry.errors[i].m2);
    }
    // Nothing outside the tile moved.
    EXPECT_EQ(other.samples[0], 0u);

    // A carry of another shape: refused, not read past its end.
    ByteReader<> wrong(reinterpret_cast<const unsigned char*>(out.bytes().data()),
                       out.bytes().size(), "short");
    EXPECT_THROW(read_carry(wrong, other, tiles[0]), std::runtime_error);
    ByteReader<> cut(reinterpret_cast<const unsigned char*>(out.bytes().data()),
                     out.bytes().size() / 2, "short");
    EXPECT_THROW(read_carry(cut, other, edge), std::runtime_error);
}

}  // namespace
}  // namespace glint
