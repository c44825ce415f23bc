// The three point patterns behind Sampler: regular grid centres, correlated multi-jittered
// points (Kensler 2013) and shuffled, Owen-scrambled Sobol points (Burley 2020). Each pattern is
// keyed by (seed, pixel, dimension), so that every dimension of every pixel gets its own.
#include "glint/sampling/sampler.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <utility>

#include "glint/sampling/random.h"

namespace glint {

namespace {

// The seed's part of every pattern's key, worked out once per sampler.
std::uint64_t seed_key(std::uint64_t seed) { return mix64(seed + 0x9e3779b97f4a7c15ull); }

// A uniform float in [0, 1) from a key and an index.
float jitter(std::uint64_t key, std::uint32_t index) {
    return float(mix64(key ^ (std::uint64_t(index) * 0x632be59bd9b4e019ull)) >> 40) * 0x1.0p-24f;
}

// Two, from the two halves of one hash's 48 top bits.
Point2 jitter_2d(std::uint64_t key, std::uint32_t index) {
    const std::uint64_t h = mix64(key ^ (std::uint64_t(index) * 0x632be59bd9b4e019ull));
    return {float(h >> 40) * 0x1.0p-24f, float((h >> 16) & 0xffffff) * 0x1.0p-24f};
}

// A permutation of [0, size) chosen by a hashed key (PatternKeys): a keyed bijection of the
// smallest power-of-two range that holds size (multiplication by an odd number and xor-shifts are
// both invertible modulo 2^bits), walked along its cycle until it lands inside [0, size).
std::uint32_t permute(std::uint32_t i, std::uint32_t size, std::uint64_t k1) {
    if (size <= 1) return 0;
    const int bits = std::bit_width(size - 1);  // of the power-of-two range
    const std::uint32_t mask = (std::uint32_t(1) << bits) - 1;
    const int shift = std::max(1, bits / 2);
    // The second round key from the first: multiplying by an odd constant is a bijection that
    // spreads k1's bits as well, at a fraction of a second hash's latency.
    const std::uint64_t k2 = k1 * 0x9e3779b97f4a7c15ull;
    do {
        i = (i ^ std::uint32_t(k1)) & mask;
        i = (i * (std::uint32_t(k1 >> 32) | 1)) & mask;
        i ^= i >> shift;
        i = (i ^ std::uint32_t(k2)) & mask;
        i = (i * (std::uint32_t(k2 >> 32) | 1)) & mask;
        i ^= i >> shift;
        i = (i * 0x2c1b3c6du) & mask;
        i ^= i >> 1;
    } while (i >= size);
    return i;
}

// The grid of a pattern of `count` points: `columns` x `rows` cells, exactly one point each.
// The factors are the two closest to sqrt(count), so that square counts give square grids and
// a prime count a single row. (A grid with a partly empty last row, Kensler's layout for any
// count, leaves that row's strip under-sampled: a biased estimate.)
struct Grid {
    std::uint32_t columns, rows;
};

Grid grid_for(std::uint32_t count) {
    auto rows = std::uint32_t(std::sqrt(double(count)));
    while (std::uint64_t(rows) * rows > count) --rows;  // if sqrt rounded up
    while (count % rows != 0) --rows;
    return {count / rows, rows};
}

// Out of line, as jittered_2d: inlined, their registers would be saved for Sobol's points too.
[[gnu::noinline]] Point2 regular_2d(std::uint32_t index, std::uint32_t count,
                                    std::uint32_t dimension, const PatternKeys& keys) {
    const Grid g = grid_for(count);
    // The pixel position keeps scanline order (sample i in cell (i mod n, i div n)); the other
    // dimensions shuffle the cells, so that dimensions do not move in lockstep.
    const std::uint32_t cell =
        dimension == kPixelDimension ? index : permute(index, count, keys.cells);
    return {(float(cell % g.columns) + 0.5f) / float(g.columns),
            (float(cell / g.columns) + 0.5f) / float(g.rows)};
}

// Kensler's correlated multi-jitter: point s lies in cell (s mod m, s div m) of the m x n grid,
// and inside it in the sub-cell that permutations of the rows and columns choose, so that the
// points also stratify the m n x m n fine grid's rows and columns.
[[gnu::noinline]] Point2 jittered_2d(std::uint32_t index, std::uint32_t count, Grid g,
                                     const PatternKeys& keys) {
    const std::uint32_t s = permute(index, count, keys.cells);
    const std::uint32_t column = s % g.columns, row = s / g.columns;
    const std::uint32_t sx = permute(column, g.columns, keys.columns);
    const std::uint32_t sy = permute(row, g.rows, keys.rows);
    const Point2 j = jitter_2d(keys.key ^ 0x1b873593ull, s);
    // (column + (sy + jx) / rows) / columns with one division: the integers are exact in float.
    const float n = float(g.columns * g.rows);
    const float x = (float(column * g.rows + sy) + j.x) / n;
    const float y = (float(row * g.columns + sx) + j.y) / n;
    // Rounding may reach 1 for the last cell; the contract is [0, 1).
    return {std::min(x, 0x1.fffffep-1f), std::min(y, 0x1.fffffep-1f)};
}

constexpr std::uint32_t reverse_bits(std::uint32_t x) {
    x = (x << 16) | (x >> 16);
    x = ((x & 0x00ff00ffu) << 8) | ((x & 0xff00ff00u) >> 8);
    x = ((x & 0x0f0f0f0fu) << 4) | ((x & 0xf0f0f0f0u) >> 4);
    x = ((x & 0x33333333u) << 2) | ((x & 0xccccccccu) >> 2);
    return ((x & 0x55555555u) << 1) | ((x & 0xaaaaaaaau) >> 1);
}

// Laine and Karras' hash, in Burley's (2020) improved form: each output bit depends only on the
// bits below it, which makes reverse_bits(hash(reverse_bits(x))) a nested uniform (Owen)
// scramble. The code below keeps values bit-reversed between scrambles, so that the reversals in
// between cancel: a reversal costs more than the hash.
std::uint32_t laine_karras_permutation(std::uint32_t x, std::uint32_t seed) {
    x += seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return x;
}

// The Sobol sequence's dimensions 1 to 5 from their direction numbers, the first rows of Joe and
// Kuo's table (2008): the primitive polynomial's degree s and inner coefficients a, and the first
// s direction numbers m_k (odd, below 2^k). Dimension 0 is the van der Corput sequence (the
// index's bits reversed), and dimension 1's matrix is Pascal's triangle modulo 2.
struct DirectionNumbers {
    int degree;
    unsigned coefficients;
    std::array<std::uint32_t, 5> first;
};

constexpr std::array<DirectionNumbers, 5> kJoeKuo{{
    {1, 0, {1}},
    {2, 1, {1, 3}},
    {3, 1, {1, 3, 1}},
    {3, 2, {1, 1, 1}},
    {4, 1, {1, 1, 3, 3}},
}};

// A dimension's generator matrix applied a byte of the index at a time: the index is scrambled,
// so all 32 of its bits are set as often as not, and a loop over them with a branch a bit took a
// third of a path tracer's time. Both sides are kept bit-reversed: the tables take the scrambled
// index as the hash leaves it (its bits reversed) and give the point's bits reversed, as the Owen
// scramble takes them.
struct SobolTables {
    std::array<std::array<std::uint32_t, 256>, 4> byte;
};

constexpr SobolTables make_sobol_tables(const DirectionNumbers& d) {
    // Sobol's recurrence: m_k = 2 a_1 m_(k-1) ^ 4 a_2 m_(k-2) ^ ... ^ 2^s m_(k-s) ^ m_(k-s).
    std::array<std::uint32_t, 33> m{};
    for (int k = 1; k <= d.degree; ++k) m[std::size_t(k)] = d.first[std::size_t(k - 1)];
    for (int k = d.degree + 1; k <= 32; ++k) {
        const std::uint32_t back = m[std::size_t(k - d.degree)];
        std::uint32_t v = back ^ (back << d.degree);
        for (int j = 1; j < d.degree; ++j)
            if ((d.coefficients >> (d.degree - 1 - j)) & 1) v ^= m[std::size_t(k - j)] << j;
        m[std::size_t(k)] = v;
    }
    // The column of index bit k - 1 is m_k / 2^k, as a 32-bit fraction; that index bit is bit
    // 32 - k of the reversed index.
    SobolTables t{};
    for (int b = 0; b < 4; ++b)
        for (std::uint32_t value = 0; value < 256; ++value)
            for (int bit = 0; bit < 8; ++bit)
                if (value & (1u << bit)) {
                    const int k = 32 - (8 * b + bit);
                    t.byte[std::size_t(b)][value] ^= reverse_bits(m[std::size_t(k)] << (32 - k));
                }
    return t;
}

template <std::size_t... D>
constexpr std::array<SobolTables, sizeof...(D)> make_all_sobol_tables(std::index_sequence<D...>) {
    return {make_sobol_tables(kJoeKuo[D])...};
}

// Tables [d - 1] for Sobol dimension d.
constexpr std::array<SobolTables, kJoeKuo.size()> kSobolTables =
    make_all_sobol_tables(std::make_index_sequence<kJoeKuo.size()>());

// Sobol dimension d in [0, 5] (unscrambled) of the index whose bits reversed are r, with the
// point's bits reversed: for the van der Corput dimension 0, the index itself.
std::uint32_t reversed_sobol(int d, std::uint32_t r) {
    if (d == 0) return reverse_bits(r);
    const auto& t = kSobolTables[std::size_t(d - 1)].byte;
    return t[0][r & 255] ^ t[1][(r >> 8) & 255] ^ t[2][(r >> 16) & 255] ^ t[3][r >> 24];
}

// The index's nested uniform scramble by `seed`, its bits reversed: the Owen scramble without
// its last reversal, which the tables take back.
std::uint32_t reversed_scrambled_index(std::uint32_t index, std::uint32_t seed) {
    return laine_karras_permutation(reverse_bits(index), seed);
}

// Sobol dimension d of the scrambled index whose bits reversed are r, Owen-scrambled by `seed`,
// its bits still reversed. Inlined: a call, twice a point, cost a tenth of the point.
[[gnu::always_inline]] inline std::uint32_t reversed_scrambled_sobol(int d, std::uint32_t r,
                                                                     std::uint32_t seed) {
    return laine_karras_permutation(reversed_sobol(d, r), seed);
}

float to_unit(std::uint32_t x) { return float(x >> 8) * 0x1.0p-24f; }

// Two reversed 32-bit fractions as a point: both reversed at once, as one 64-bit word.
Point2 unit_point_of_reversed(std::uint32_t x, std::uint32_t y) {
    std::uint64_t v = std::uint64_t(x) | (std::uint64_t(y) << 32);
    v = (v << 32) | (v >> 32);
    v = ((v & 0x0000ffff0000ffffull) << 16) | ((v >> 16) & 0x0000ffff0000ffffull);
    v = ((v & 0x00ff00ff00ff00ffull) << 8) | ((v >> 8) & 0x00ff00ff00ff00ffull);
    v = ((v & 0x0f0f0f0f0f0f0f0full) << 4) | ((v >> 4) & 0x0f0f0f0f0f0f0f0full);
    v = ((v & 0x3333333333333333ull) << 2) | ((v >> 2) & 0x3333333333333333ull);
    v = ((v & 0x5555555555555555ull) << 1) | ((v >> 1) & 0x5555555555555555ull);
    // The whole word reversed: x's bits reversed are the upper half.
    return {to_unit(std::uint32_t(v >> 32)), to_unit(std::uint32_t(v))};
}

// Which of Sobol's dimensions the camera's dimensions take when their points are the pixel's
// samples (one a sample): the pixel position, the lens, and the time and the wavelength when drawn
// as one number. Others are padded (joint_sobol_none). The integrators' own dimensions stay
// padded: lights and lobes drawn jointly with the pixel gained little (2% less error on
// bench/distributed_vs_povray) and would change what each particle of the light and photon
// integrators draws.
constexpr int joint_sobol_none = -1;
struct JointSobol {
    int x, y;
};
constexpr std::array<JointSobol, 4> kJointSobol{{
    {0, 1},                 // kPixelDimension
    {2, 3},                 // kLensDimension
    {4, joint_sobol_none},  // kTimeDimension, one number
    {5, joint_sobol_none},  // kWavelengthDimension, one number
}};
static_assert(kFirstFreeDimension == kJointSobol.size());

// Burley's shuffled scrambled Sobol. The joint dimensions' index is scrambled by the pixel's key,
// the same for them all, which keeps them one sequence; every other dimension's index by its own,
// which decorrelates it from the rest. Scrambling the index keeps every aligned block of 2^k
// indices a net.
Point2 sobol_2d(std::uint32_t index, const PatternKeys& keys, JointSobol joint) {
    const std::uint64_t k = keys.cells;
    const bool together = joint.y != joint_sobol_none;
    const std::uint32_t r =
        reversed_scrambled_index(index, std::uint32_t(together ? keys.pixel : keys.key));
    const int dx = together ? joint.x : 0, dy = together ? joint.y : 1;
    return unit_point_of_reversed(reversed_scrambled_sobol(dx, r, std::uint32_t(k)),
                                  reversed_scrambled_sobol(dy, r, std::uint32_t(k >> 32)));
}

float sobol_1d(std::uint32_t index, const PatternKeys& keys, JointSobol joint) {
    const bool together = joint.x != joint_sobol_none;
    const std::uint32_t r =
        reversed_scrambled_index(index, std::uint32_t(together ? keys.pixel : keys.key));
    return to_unit(reverse_bits(
        reversed_scrambled_sobol(together ? joint.x : 0, r, std::uint32_t(keys.cells))));
}

// The joint dimensions of `dimension`, when its pattern is the pixel's samples.
JointSobol joint_sobol(std::uint32_t dimension, std::uint32_t count, int spp) {
    if (count != std::uint32_t(spp) || dimension >= kJointSobol.size())
        return {joint_sobol_none, joint_sobol_none};
    return kJointSobol[dimension];
}

}  // namespace

namespace {
constexpr std::string_view kSamplerNames[] = {"jittered", "regular", "sobol"};
constexpr SamplerKind kSamplerKinds[] = {SamplerKind::jittered, SamplerKind::regular,
                                         SamplerKind::sobol};
}  // namespace

std::span<const std::string_view> sampler_names() { return kSamplerNames; }

std::optional<SamplerKind> sampler_from_name(std::string_view name) {
    for (std::size_t i = 0; i < std::size(kSamplerNames); ++i)
        if (kSamplerNames[i] == name) return kSamplerKinds[i];
    return std::nullopt;
}

bool is_valid_sample_count(SamplerKind kind, int samples_per_pixel) {
    if (samples_per_pixel < 1) return false;
    if (kind != SamplerKind::regular) return true;
    const auto n = std::lround(std::sqrt(double(samples_per_pixel)));
    return n * n == samples_per_pixel;
}

Sampler::Sampler(SamplerKind kind, int samples_per_pixel, std::uint64_t seed)
    : kind_(kind), spp_(samples_per_pixel), seed_(seed), seed_key_(seed_key(seed)) {
    const Grid g = grid_for(std::uint32_t(std::max(samples_per_pixel, 1)));
    pixel_columns_ = g.columns;
    pixel_rows_ = g.rows;
}

PatternKeys Sampler::pattern_keys(std::uint64_t pixel, std::uint32_t dimension) const {
    const std::uint64_t pixel_key = mix64(seed_key_ ^ pixel);
    const std::uint64_t key = mix64(pixel_key ^ (std::uint64_t(dimension) * 0x8cb92ba72f3d8dd7ull));
    return {key, mix64(key), mix64(key ^ 0xa511e9b3a511e9b3ull), mix64(key ^ 0x63d8359563d83595ull),
            pixel_key};
}

Point2 Sampler::pattern_2d(const PatternKeys& keys, std::uint32_t index, std::uint32_t count,
                           std::uint32_t dimension) const {
    switch (kind_) {
        case SamplerKind::regular:
            return regular_2d(index, count, dimension, keys);
        case SamplerKind::jittered:
            // Most patterns have one point a sample: the pixel's grid, worked out once.
            return jittered_2d(
                index, count,
                count == std::uint32_t(spp_) ? Grid{pixel_columns_, pixel_rows_} : grid_for(count),
                keys);
        case SamplerKind::sobol:
            return sobol_2d(index, keys, joint_sobol(dimension, count, spp_));
    }
    return {0.5f, 0.5f};
}

float Sampler::get_1d(const PatternKeys& keys, std::uint32_t index, std::uint32_t count,
                      std::uint32_t dimension) const {
    switch (kind_) {
        case SamplerKind::regular:
            return (float(permute(index, count, keys.cells)) + 0.5f) / float(count);
        case SamplerKind::jittered:
            return std::min(
                (float(permute(index, count, keys.cells)) + jitter(keys.key, index)) / float(count),
                0x1.fffffep-1f);
        case SamplerKind::sobol:
            return sobol_1d(index, keys, joint_sobol(dimension, count, spp_));
    }
    return 0.5f;
}

}  // namespace glint
