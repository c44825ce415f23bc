// Parts of a render: which pieces each takes, and their states added into the whole's. Every
// sum the film, the particles' film and the counts keep is added; what a pixel's own tile
// decides (its samples, its adaptive error, the one-pixel film's float sums) comes from the
// part that rendered the tile.
#include "glint/render/render_part.h"

#include <algorithm>
#include <charconv>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <utility>

#include "glint/render/state_sums.h"
#include "glint/render/tile_carry.h"
#include "glint/render/tiles.h"

namespace glint {

namespace {

// The passes [first, last) of a sample-pass part of a render of `passes` passes.
std::pair<int, int> part_passes(const RenderPart& part, int passes) {
    const auto at = [&](int index) { return int(std::int64_t(index) * passes / part.count); };
    return {at(part.index - 1), at(part.index)};
}

bool owns_tile(const RenderPart& part, std::size_t tile) {
    return int(tile % std::size_t(part.count)) == part.index - 1;
}

}  // namespace

std::optional<RenderPart> parse_render_part(std::string_view text, PartSplit split) {
    const std::size_t slash = text.find('/');
    if (slash == std::string_view::npos) return std::nullopt;
    const auto whole = [](std::string_view digits) -> std::optional<int> {
        int value = 0;
        const auto [end, error] =
            std::from_chars(digits.data(), digits.data() + digits.size(), value);
        if (digits.empty() || error != std::errc{} || end != digits.data() + digits.size())
            return std::nullopt;
        return value;
    };
    const auto index = whole(text.substr(0, slash)), count = whole(text.substr(slash + 1));
    if (!index || !count || *count < 1 || *count > 100000 || *index < 1 || *index > *count)
        return std::nullopt;
    return RenderPart{*index, *count, split};
}

std::string describe(const RenderPart& part) {
    return "part " + std::to_string(part.index) + " of " + std::to_string(part.count) + " (" +
           std::string(kPartSplitNames[std::size_t(part.split)]) + ")";
}

std::optional<std::string> part_refusal(const RenderPart& part, const RenderSettings& settings,
                                        const RenderState& state) {
    if (part.whole()) return std::nullopt;
    const int tiles = int(state.tile_passes.size());
    if (part.split == PartSplit::tiles) {
        if (tiles < part.count)
            return "the image has " + std::to_string(tiles) + " tiles, too few for " +
                   std::to_string(part.count) + " parts: make the tiles smaller or the parts fewer";
        return std::nullopt;
    }
    if (settings.adaptive)
        return std::string(
            "adaptive sampling decides each pass from the passes before it: split its render "
            "by tiles");
    const int passes = pass_count(settings.samples_per_pixel, state.pass_size);
    if (passes < part.count)
        return "the render has " + std::to_string(passes) + " passes of " +
               std::to_string(state.pass_size) + " samples, too few for " +
               std::to_string(part.count) + " parts: split it by tiles, or into fewer parts";
    return std::nullopt;
}

void start_part(RenderState& state, const RenderPart& part, int passes) {
    if (part.split != PartSplit::passes || part.whole()) return;
    // The samples of the passes before are another part's: the pixels start past them.
    const int first = part_passes(part, passes).first;
    std::fill(state.tile_passes.begin(), state.tile_passes.end(), first);
    std::fill(state.samples.begin(), state.samples.end(), std::uint32_t(first * state.pass_size));
}

std::vector<WorkPiece> part_work(const RenderState& state, const RenderPart& part, int passes) {
    if (part.split == PartSplit::passes) {
        const int last = part_passes(part, passes).second;
        return remaining_work(state, last);
    }
    std::vector<WorkPiece> work;
    for (const WorkPiece& piece : remaining_work(state, passes))
        if (owns_tile(part, std::size_t(piece.tile))) work.push_back(piece);
    return work;
}

bool part_done(const RenderState& state, const RenderPart& part, int passes) {
    if (part.split == PartSplit::passes)
        return state.passes_done() >= part_passes(part, passes).second;
    for (std::size_t tile = 0; tile < state.tile_passes.size(); ++tile)
        if (owns_tile(part, tile) && state.tile_passes[tile] < passes) return false;
    return true;
}

RenderState merge_parts(std::vector<RenderState> parts, PartSplit split, int tile_size) {
    if (parts.empty()) throw std::invalid_argument("merge_parts: no parts");
    RenderState whole = std::move(parts.front());
    const int count = int(parts.size());
    std::vector<BoxSum>& box_sums = whole.film.box_sums();
    const std::vector<Tile> tiles = make_tiles(whole.width, whole.height, tile_size);
    if (tiles.size() != whole.tile_passes.size())
        throw std::invalid_argument("merge_parts: the tile size is not the parts'");
    for (int i = 1; i < count; ++i) {
        RenderState& part = parts[std::size_t(i)];
        if (part.width != whole.width || part.height != whole.height ||
            part.pass_size != whole.pass_size ||
            part.film.sums().size() != whole.film.sums().size() ||
            part.film.box_sums().size() != box_sums.size() ||
            part.errors.size() != whole.errors.size() ||
            part.splats.has_value() != whole.splats.has_value())
            throw std::invalid_argument("merge_parts: the parts are of different renders");
        add_sums(whole, part);  // integer sums: exact in any order
        whole.rays += part.rays;
        whole.bad_samples += part.bad_samples;
        whole.seconds += part.seconds;
        if (split == PartSplit::passes) {
            // Part after part, in the order of their samples.
            for (std::size_t p = 0; p < box_sums.size(); ++p) {
                box_sums[p].sum += part.film.box_sums()[p].sum;
                box_sums[p].weight += part.film.box_sums()[p].weight;
            }
            for (std::size_t p = 0; p < whole.samples.size(); ++p)
                whole.samples[p] = std::max(whole.samples[p], part.samples[p]);
            for (std::size_t t = 0; t < whole.tile_passes.size(); ++t)
                whole.tile_passes[t] = std::max(whole.tile_passes[t], part.tile_passes[t]);
            continue;
        }
        // The tiles this part rendered: their carries (pixels' samples, errors, sums) are its.
        for (std::size_t t = std::size_t(i); t < tiles.size(); t += std::size_t(count)) {
            whole.tile_passes[t] = part.tile_passes[t];
            put_carry(whole, tiles[t], take_carry(part, tiles[t], int(t)));
        }
    }
    return whole;
}

}  // namespace glint
