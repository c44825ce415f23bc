// One of N parts of a render, for machines that share a folder or a batch scheduler's job array:
// each renders its part into a state of its own, and merge_parts adds the states into the state
// one render of the whole gives. Parts are tiles (every Nth tile, through every pass) or sample
// passes (a run of consecutive passes over every tile).
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "glint/render/render.h"

namespace glint {

enum class PartSplit { tiles, passes };
inline constexpr std::string_view kPartSplitNames[] = {"tiles", "passes"};  // by PartSplit

struct RenderPart {
    int index = 1;  // 1 to count
    int count = 1;
    PartSplit split = PartSplit::tiles;
    bool whole() const { return count == 1; }
    bool operator==(const RenderPart&) const = default;
};

// "3/8" -> part 3 of 8; nullopt for anything else (I from 1 to N, N from 1 to 100000).
std::optional<RenderPart> parse_render_part(std::string_view text, PartSplit split);
// "part 3 of 8 (tiles)".
std::string describe(const RenderPart& part);

// Why a render of `settings` in `state`'s tiles and passes cannot be split so; nullopt if it
// can. Sample passes need a render without adaptive sampling (whose passes depend on those
// before) and at least as many passes as parts; tiles at least as many tiles.
std::optional<std::string> part_refusal(const RenderPart& part, const RenderSettings& settings,
                                        const RenderState& state);

// The state a part of a render of `passes` passes starts from: a fresh render's, or for sample
// passes one whose tiles and pixels are at the part's first pass, its film empty.
void start_part(RenderState& state, const RenderPart& part, int passes);

// The part's pieces left to do in `state` (started by start_part), in render()'s order.
std::vector<WorkPiece> part_work(const RenderState& state, const RenderPart& part, int passes);

// Whether the part is done in `state`.
bool part_done(const RenderState& state, const RenderPart& part, int passes);

// The state of the whole render, in tiles of tile_size, from its parts' finished states,
// `parts[i]` being part i + 1 of parts.size(), split as `split`. Tile parts give the whole render's
// state bit for bit; sample pass parts too, but for the film of the one-pixel box and of filter
// importance sampling, whose float sums the merge adds part after part instead of sample after
// sample: within float rounding. The time is the parts' summed.
RenderState merge_parts(std::vector<RenderState> parts, PartSplit split, int tile_size);

}  // namespace glint
