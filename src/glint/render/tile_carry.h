// What of a render's state belongs to one tile's own pixels and carries on from one of its passes
// to the next: each pixel's samples taken and adaptive error, the one-pixel films' float sums (the
// image's and the output variables'), which add sample after sample, and the ids of each pixel's
// first sample. A rank renders a tile's next pass from the carry the pass before left, so that a
// tile's passes may go to any ranks and the image stays one process's, bit for bit.
#pragma once

#include <cstdint>
#include <vector>

#include "glint/render/byte_stream.h"
#include "glint/render/render_state.h"
#include "glint/render/tiles.h"

namespace glint {

struct TileCarry {
    int tile = -1;  // its index in make_tiles order
    std::vector<std::uint32_t> samples;
    std::vector<PixelError> errors;  // under adaptive sampling
    // The image's one-pixel film, then each one-pixel output variable's, row by row in the tile.
    std::vector<BoxSum> box_sums;
    std::vector<std::int32_t> objects, materials;  // when those output variables are asked for
};

// The carry of tile `index` (its pixels `tile`) in `state`.
TileCarry take_carry(const RenderState& state, const Tile& tile, int index);
// Puts a carry taken from a state of the same render back into `state`.
void put_carry(RenderState& state, const Tile& tile, const TileCarry& carry);

void write_carry(ByteWriter& out, const TileCarry& carry);
// Throws std::runtime_error on a message too short or sizes that do not fit `tile` in `state`.
TileCarry read_carry(ByteReader<>& in, const RenderState& state, const Tile& tile);

}  // namespace glint
