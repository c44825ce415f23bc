// The sums of a render's state that add in any order: the fixed-point sums of the film and of the
// output variables' films under a filter wider than a pixel, and the particles' film. Two states
// of one render that took different pieces add into the state that took both, exactly; so parts
// of a render merge, and the ranks of a cluster sum their films.
#pragma once

#include <cstddef>
#include <span>

#include "glint/render/render_state.h"

namespace glint {

// Adds `from`'s sums into `into`'s: states of one render (same image, filter and variables).
void add_sums(RenderState& into, const RenderState& from);

// The sums as one array, each a FixedSum (a particle sum widened): its length, and a run of
// it copied out or written back, so that a large film moves in pieces.
std::size_t sum_count(const RenderState& state);
void copy_sums(const RenderState& state, std::size_t first, std::span<FixedSum> out);
void write_sums(RenderState& state, std::size_t first, std::span<const FixedSum> in);

}  // namespace glint
