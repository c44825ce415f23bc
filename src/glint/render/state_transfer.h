// A whole render state as bytes, output variables included: what a rank of a cluster that
// rendered a frame alone sends to rank 0, which writes the frame's image, or its partial image
// and resume file, as if it had rendered the frame itself. Unlike a resume file's, nothing is
// left out, and the bytes are never kept: they go between two ranks of one glint.
#pragma once

#include "glint/render/byte_stream.h"
#include "glint/render/render_state.h"

namespace glint {

// Every tile's carry (tile_carry.h) in tiles of `tile_size`, the films' sums (state_sums.h),
// the passes each tile did, the counts and the time.
void write_state(ByteWriter& out, const RenderState& state, int tile_size);

// Reads into `state`, a fresh state of the same render (initial_state with the same settings
// and options). Throws std::runtime_error on bytes too short, or sizes that do not fit it.
void read_state(ByteReader<>& in, RenderState& state, int tile_size);

}  // namespace glint
