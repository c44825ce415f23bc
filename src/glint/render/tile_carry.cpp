// A tile's carry: its pixels' entries of each per-pixel array of the state, row by row.
#include "glint/render/tile_carry.h"

#include <stdexcept>

namespace glint {

namespace {

// Calls f(pixel index in the image) for the tile's pixels, row by row.
template <class F>
void for_pixels(const RenderState& state, const Tile& tile, F&& f) {
    for (int y = tile.y0; y < tile.y1; ++y)
        for (int x = tile.x0; x < tile.x1; ++x)
            f(std::size_t(y) * std::size_t(state.width) + std::size_t(x));
}

// The one-pixel films of the state: the image's and the output variables', in that order.
template <class State, class F>
void for_box_films(State& state, F&& f) {
    if (state.film.one_pixel()) f(state.film.box_sums());
    for (auto& [aov, film] : state.aovs.films())
        if (film.one_pixel()) f(film.box_sums());
}

std::size_t box_film_count(const RenderState& state) {
    std::size_t n = 0;
    for_box_films(state, [&](const auto&) { ++n; });
    return n;
}

}  // namespace

TileCarry take_carry(const RenderState& state, const Tile& tile, int index) {
    TileCarry carry;
    carry.tile = index;
    const auto& objects = state.aovs.objects();
    const auto& materials = state.aovs.materials();
    for_pixels(state, tile, [&](std::size_t p) {
        carry.samples.push_back(state.samples[p]);
        if (!state.errors.empty()) carry.errors.push_back(state.errors[p]);
        if (!objects.empty()) carry.objects.push_back(objects[p]);
        if (!materials.empty()) carry.materials.push_back(materials[p]);
    });
    for_box_films(state, [&](const std::vector<BoxSum>& sums) {
        for_pixels(state, tile, [&](std::size_t p) { carry.box_sums.push_back(sums[p]); });
    });
    return carry;
}

void put_carry(RenderState& state, const Tile& tile, const TileCarry& carry) {
    std::size_t i = 0;
    auto& objects = state.aovs.objects();
    auto& materials = state.aovs.materials();
    for_pixels(state, tile, [&](std::size_t p) {
        state.samples[p] = carry.samples[i];
        if (!state.errors.empty()) state.errors[p] = carry.errors[i];
        if (!objects.empty()) objects[p] = carry.objects[i];
        if (!materials.empty()) materials[p] = carry.materials[i];
        ++i;
    });
    std::size_t b = 0;
    for_box_films(state, [&](std::vector<BoxSum>& sums) {
        for_pixels(state, tile, [&](std::size_t p) { sums[p] = carry.box_sums[b++]; });
    });
}

void write_carry(ByteWriter& out, const TileCarry& carry) {
    out.i32(carry.tile);
    out.u8(carry.errors.empty() ? 0 : 1);
    out.u8(carry.objects.empty() ? 0 : 1);
    out.u8(carry.materials.empty() ? 0 : 1);
    out.u32(std::uint32_t(carry.box_sums.size()));
    for (const std::uint32_t n : carry.samples) out.u32(n);
    for (const PixelError& e : carry.errors) {
        out.i32(e.n);
        out.f64(e.mean);
        out.f64(e.m2);
    }
    for (const BoxSum& b : carry.box_sums) {
        out.f32(b.sum.r);
        out.f32(b.sum.g);
        out.f32(b.sum.b);
        out.f32(b.weight);
    }
    for (const std::int32_t id : carry.objects) out.i32(id);
    for (const std::int32_t id : carry.materials) out.i32(id);
}

TileCarry read_carry(ByteReader<>& in, const RenderState& state, const Tile& tile) {
    TileCarry carry;
    carry.tile = in.i32();
    const bool errors = in.u8() != 0, objects = in.u8() != 0, materials = in.u8() != 0;
    const std::size_t pixels = std::size_t(tile.x1 - tile.x0) * std::size_t(tile.y1 - tile.y0);
    const std::size_t box_sums = in.u32();
    if (errors != !state.errors.empty() || objects != !state.aovs.objects().empty() ||
        materials != !state.aovs.materials().empty() || box_sums != pixels * box_film_count(state))
        throw std::runtime_error("a tile's carry does not fit the render's state");
    carry.samples.resize(pixels);
    for (std::uint32_t& n : carry.samples) n = in.u32();
    if (errors) {
        carry.errors.resize(pixels);
        for (PixelError& e : carry.errors) {
            e.n = in.i32();
            e.mean = in.f64();
            e.m2 = in.f64();
        }
    }
    carry.box_sums.resize(box_sums);
    for (BoxSum& b : carry.box_sums) {
        b.sum.r = in.f32();
        b.sum.g = in.f32();
        b.sum.b = in.f32();
        b.weight = in.f32();
    }
    if (objects) {
        carry.objects.resize(pixels);
        for (std::int32_t& id : carry.objects) id = in.i32();
    }
    if (materials) {
        carry.materials.resize(pixels);
        for (std::int32_t& id : carry.materials) id = in.i32();
    }
    return carry;
}

}  // namespace glint
