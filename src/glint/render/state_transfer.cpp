// Tiles' carries for the per-pixel state, so that the tile layout and the output variables'
// films follow from one place; the sums in one run after them.
#include "glint/render/state_transfer.h"

#include <algorithm>
#include <span>
#include <stdexcept>
#include <vector>

#include "glint/render/counts_codec.h"
#include "glint/render/state_sums.h"
#include "glint/render/tile_carry.h"
#include "glint/render/tiles.h"

namespace glint {

namespace {

// The sums copied at a time: a film's are as large as the film, and the bytes hold them already.
constexpr std::size_t kSumPiece = std::size_t(1) << 20;

}  // namespace

void write_state(ByteWriter& out, const RenderState& state, int tile_size) {
    const std::vector<Tile> tiles = make_tiles(state.width, state.height, tile_size);
    out.u32(std::uint32_t(tiles.size()));
    for (std::size_t t = 0; t < tiles.size(); ++t) {
        out.i32(state.tile_passes[t]);
        write_carry(out, take_carry(state, tiles[t], int(t)));
    }
    const std::size_t n = sum_count(state);
    out.u64(n);
    std::vector<FixedSum> piece(std::min(n, kSumPiece));
    for (std::size_t first = 0; first < n; first += kSumPiece) {
        const std::span<FixedSum> sums(piece.data(), std::min(kSumPiece, n - first));
        copy_sums(state, first, sums);
        for (const FixedSum s : sums) out.i128(s);
    }
    write_counts(out, state.rays, state.bad_samples);
    out.f64(state.seconds);
}

void read_state(ByteReader<>& in, RenderState& state, int tile_size) {
    const std::vector<Tile> tiles = make_tiles(state.width, state.height, tile_size);
    if (in.u32() != tiles.size() || tiles.size() != state.tile_passes.size())
        throw std::runtime_error("a state of another image or tile size");
    for (std::size_t t = 0; t < tiles.size(); ++t) {
        state.tile_passes[t] = in.i32();
        if (state.tile_passes[t] < 0) throw std::runtime_error("a tile with passes below none");
        put_carry(state, tiles[t], read_carry(in, state, tiles[t]));
    }
    const std::size_t n = sum_count(state);
    if (in.u64() != n) throw std::runtime_error("a state with films of another size");
    std::vector<FixedSum> piece(std::min(n, kSumPiece));
    for (std::size_t first = 0; first < n; first += kSumPiece) {
        const std::span<FixedSum> sums(piece.data(), std::min(kSumPiece, n - first));
        for (FixedSum& s : sums) s = in.i128();
        write_sums(state, first, sums);
    }
    read_counts(in, state.rays, state.bad_samples);
    state.seconds = in.f64();
}

}  // namespace glint
