// The additive sums walked in one order: the film's pixels (red, green, blue, weight), each
// output variable's film likewise, then the particles' sums.
#include "glint/render/state_sums.h"

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace glint {

namespace {

// Calls f(sum) on every additive sum of `state` in array order, from index `first` for `n` sums.
template <class State, class F>
void for_sums(State& state, std::size_t first, std::size_t n, F&& f) {
    std::size_t at = 0;  // the array index of the next sum visited
    const std::size_t end = first + n;
    const auto film = [&](auto& sums) {
        const std::size_t size = sums.size() * 4;
        if (at + size > first && at < end)
            for (std::size_t i = std::max(first, at); i < std::min(end, at + size); ++i) {
                auto& pixel = sums[(i - at) / 4];
                switch ((i - at) % 4) {
                    case 0:
                        f(i - first, pixel.r);
                        break;
                    case 1:
                        f(i - first, pixel.g);
                        break;
                    case 2:
                        f(i - first, pixel.b);
                        break;
                    default:
                        f(i - first, pixel.weight);
                        break;
                }
            }
        at += size;
    };
    film(state.film.sums());
    for (auto& [aov, aov_film] : state.aovs.films()) film(aov_film.sums());
    if (state.splats) {
        const std::size_t size = state.splats->size();
        for (std::size_t i = std::max(first, at); i < std::min(end, at + size); ++i)
            f(i - first, *state.splats, i - at);
        at += size;
    }
}

}  // namespace

std::size_t sum_count(const RenderState& state) {
    std::size_t n = state.film.sums().size() * 4;
    for (const auto& [aov, film] : state.aovs.films()) n += film.sums().size() * 4;
    if (state.splats) n += state.splats->size();
    return n;
}

void copy_sums(const RenderState& state, std::size_t first, std::span<FixedSum> out) {
    struct Copy {
        std::span<FixedSum> out;
        void operator()(std::size_t i, const FixedSum& v) const { out[i] = v; }
        void operator()(std::size_t i, const SplatFilm& s, std::size_t k) const {
            out[i] = s.sum(k);
        }
    };
    for_sums(state, first, out.size(), Copy{out});
}

void write_sums(RenderState& state, std::size_t first, std::span<const FixedSum> in) {
    struct Write {
        std::span<const FixedSum> in;
        void operator()(std::size_t i, FixedSum& v) const { v = in[i]; }
        void operator()(std::size_t i, SplatFilm& s, std::size_t k) const {
            s.set_sum(k, std::int64_t(in[i]));
        }
    };
    for_sums(state, first, in.size(), Write{in});
}

void add_sums(RenderState& into, const RenderState& from) {
    const std::size_t n = sum_count(into);
    if (sum_count(from) != n) throw std::invalid_argument("add_sums: states of different renders");
    // In pieces of a mebibyte's worth.
    constexpr std::size_t kPiece = std::size_t(1) << 16;
    std::vector<FixedSum> mine(kPiece), theirs(kPiece);
    for (std::size_t first = 0; first < n; first += kPiece) {
        const std::size_t count = std::min(kPiece, n - first);
        copy_sums(into, first, {mine.data(), count});
        copy_sums(from, first, {theirs.data(), count});
        for (std::size_t i = 0; i < count; ++i) mine[i] += theirs[i];
        write_sums(into, first, {mine.data(), count});
    }
}

}  // namespace glint
