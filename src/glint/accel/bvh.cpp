// Parallel binned-SAH construction of the binary BVH, deterministic for any thread count: large
// nodes are binned and partitioned in blocks of a fixed size and their results combined in block
// order, and large subtrees are built as tasks into chunks that are laid out in a fixed order.
#include "glint/accel/bvh.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_group.h>

#include <algorithm>
#include <cassert>
#include <memory>

namespace glint {

namespace {

// SAH splits are tried only above this depth; below it ranges are halved by count, which needs
// at most 32 more levels for 2^32 primitives, so no leaf is deeper than kBvhMaxDepth - 2.
constexpr int kSahDepthLimit = kBvhMaxDepth - 34;
constexpr int kMaxBins = 64;
// Ranges of at least this many primitives are binned into two sets of bins (bin_block).
constexpr std::uint32_t kTwoBinSets = 128;
// Ranges of at least this many primitives are binned and partitioned in parallel, in blocks of
// kBlock. Both are constants, not functions of the thread count, so the result is not either.
constexpr std::uint32_t kParallelRange = 1u << 16;
constexpr std::uint32_t kBlock = 1u << 14;
// A node this large builds its second subtree as a task, into a chunk of its own.
constexpr std::uint32_t kParallelSubtree = 1u << 12;

// A box in two SIMD registers (GCC vector extensions; lane 3 unused), so that growing one by
// another is two instructions. grow() takes min and max exactly as merge(Bounds3, Bounds3) does.
typedef float Float4 __attribute__((vector_size(16)));
typedef int Int4 __attribute__((vector_size(16)));

Float4 splat(float x) { return Float4{x, x, x, x}; }

// Trivial, so that arrays of bins cost nothing to declare; empty() is the empty box.
struct Box4 {
    Float4 lo;
    Float4 hi;

    static Box4 empty() { return {splat(kInfinity), splat(-kInfinity)}; }
    static Box4 of(const Bounds3& b) {
        Box4 out;
        out.lo = Float4{b.min.x, b.min.y, b.min.z, 0};
        out.hi = Float4{b.max.x, b.max.y, b.max.z, 0};
        return out;
    }
    void grow(const Box4& b) {
        lo = b.lo < lo ? b.lo : lo;
        hi = b.hi > hi ? b.hi : hi;
    }
    void grow(Float4 p) {
        lo = p < lo ? p : lo;
        hi = p > hi ? p : hi;
    }
    Bounds3 bounds() const { return {{lo[0], lo[1], lo[2]}, {hi[0], hi[1], hi[2]}}; }
    // Zero for an empty box (and for NaN extents).
    float area() const {
        const Float4 d = hi - lo;
        if (!(d[0] >= 0 && d[1] >= 0 && d[2] >= 0)) return 0;
        return 2 * (d[0] * d[1] + d[1] * d[2] + d[2] * d[0]);
    }
};

struct Bin {
    Box4 bounds;
    std::uint32_t count;
    std::uint32_t blocked;  // of them, of kind 1

    static Bin empty() { return {Box4::empty(), 0, 0}; }
};

// A range of Bvh::primitive_indices with the union of its boxes and of its centroids.
struct Range {
    std::uint32_t begin = 0, end = 0;
    Box4 bounds = Box4::empty(), centroids = Box4::empty();

    std::uint32_t size() const { return end - begin; }
};

// Nodes of one subtree, indexed from 0 here. A node listed in `remote` has its second child in
// another chunk (built by another task); flatten() lays the chunks out one after another.
struct Chunk {
    struct Remote {
        std::uint32_t node;
        std::unique_ptr<Chunk> chunk;
    };
    LargeVector<BvhNode> nodes;
    std::vector<Remote> remote;
};

std::uint32_t blocks_of(std::uint32_t n) { return (n + kBlock - 1) / kBlock; }

// f(block_begin, block_end, block_index) over [begin, end) in kBlock pieces, in parallel.
template <typename F>
void for_blocks(std::uint32_t begin, std::uint32_t end, F&& f) {
    tbb::parallel_for(tbb::blocked_range<std::uint32_t>(0, blocks_of(end - begin), 1),
                      [&](const tbb::blocked_range<std::uint32_t>& r) {
                          for (std::uint32_t k = r.begin(); k != r.end(); ++k) {
                              const std::uint32_t b = begin + k * kBlock;
                              f(b, std::min(end, b + kBlock), k);
                          }
                      });
}

class Builder {
public:
    Builder(std::span<const Bounds3> bounds, const BvhBuildOptions& options,
            std::span<const std::uint8_t> kinds, Bvh& bvh)
        : indices_(bvh.primitive_indices), kinds_(kinds) {
        max_leaf_ = std::uint32_t(std::clamp(options.max_leaf_size, 1, 255));
        bins_ = std::clamp(options.bins, 2, kMaxBins);
        traversal_cost_ = options.traversal_cost;
        block_size_ = std::uint32_t(std::clamp(options.block_size, 1, 16));
        shape_cost_ = options.shape_cost;
        const auto n = std::uint32_t(bounds.size());
        boxes_.resize(n);
        centroids_.resize(n);
        scratch_.resize(n);
        for_blocks(0, n, [&](std::uint32_t b, std::uint32_t e, std::uint32_t) {
            for (std::uint32_t i = b; i < e; ++i) {
                indices_[i] = i;
                boxes_[i] = Box4::of(bounds[i]);
                const Point3 c = bounds[i].center();
                centroids_[i] = Float4{c.x, c.y, c.z, 0};
            }
        });
    }

    Range root() const {
        Range r{0, std::uint32_t(boxes_.size())};
        measure(r);
        return r;
    }

    // Appends the subtree over r to chunk.nodes, depth first, its root at the end on entry.
    void build(const Range& r, int depth, Chunk& chunk) {
        const auto node_index = std::uint32_t(chunk.nodes.size());
        chunk.nodes.emplace_back();
        chunk.nodes[node_index].bounds = r.bounds.bounds();
        Range left, right;
        int axis = 0;
        if (!split(r, depth, left, right, axis)) {
            assert(r.size() >= 1 && r.size() <= 255);
            chunk.nodes[node_index].offset = r.begin;
            chunk.nodes[node_index].count = std::uint16_t(r.size());
            return;
        }
        chunk.nodes[node_index].axis = std::uint8_t(axis);
        if (r.size() < kParallelSubtree) {
            build(left, depth + 1, chunk);
            chunk.nodes[node_index].offset = std::uint32_t(chunk.nodes.size());
            build(right, depth + 1, chunk);
            return;
        }
        // The second subtree goes to a chunk of its own while this thread builds the first in
        // place; the chunk's position in the list (and so in the final array) does not depend on
        // which finishes first.
        auto other = std::make_unique<Chunk>();
        Chunk& other_chunk = *other;
        chunk.remote.push_back({node_index, std::move(other)});
        tbb::task_group group;
        group.run([&, right, depth] { build(right, depth + 1, other_chunk); });
        build(left, depth + 1, chunk);
        group.wait();
    }

private:
    // The union of the boxes and of the centroids of r's primitives, into r.
    void measure(Range& r) const {
        const auto fold = [&](std::uint32_t b, std::uint32_t e, Box4& bounds, Box4& cent) {
            for (std::uint32_t i = b; i < e; ++i) {
                const std::uint32_t p = indices_[i];
                bounds.grow(boxes_[p]);
                cent.grow(centroids_[p]);
            }
        };
        r.bounds = r.centroids = Box4::empty();
        if (r.size() < kParallelRange) return fold(r.begin, r.end, r.bounds, r.centroids);
        std::vector<Box4> bounds(blocks_of(r.size()), Box4::empty()), cents(bounds);
        for_blocks(r.begin, r.end, [&](std::uint32_t b, std::uint32_t e, std::uint32_t k) {
            fold(b, e, bounds[k], cents[k]);
        });
        // In block order: with NaN coordinates, min and max depend on the order they are taken in.
        for (std::size_t k = 0; k < bounds.size(); ++k) {
            r.bounds.grow(bounds[k]);
            r.centroids.grow(cents[k]);
        }
    }

    static int longest_axis(const Box4& b) {
        const Float4 d = b.hi - b.lo;
        // Written so that a NaN extent never wins.
        int axis = 0;
        if (d[1] > d[axis]) axis = 1;
        if (d[2] > d[axis]) axis = 2;
        return axis;
    }

    // Splits r in two, or returns false for a leaf (at most max_leaf_ tests, of one kind).
    bool split(const Range& r, int depth, Range& left, Range& right, int& axis) {
        const std::uint32_t count = r.size();
        if (count <= 1) return false;
        if (depth < kSahDepthLimit && sah_split(r, left, right, axis)) return true;
        axis = longest_axis(r.centroids);
        if (!fits_leaf(r)) {
            median_split(r, axis, left, right);
            return true;
        }
        return split_by_kind(r, left, right);
    }

    // Splits a range that would be a leaf of mixed kinds: the lowest kind to the left. Ranges
    // this small are leaves, so this happens at most once on a path for two kinds; with k kinds
    // at most k - 1 times, and kBvhMaxDepth leaves room for a few.
    bool split_by_kind(const Range& r, Range& left, Range& right) {
        if (kinds_.empty()) return false;
        std::uint8_t lowest = 255, highest = 0;
        for (std::uint32_t i = r.begin; i < r.end; ++i) {
            lowest = std::min(lowest, kinds_[indices_[i]]);
            highest = std::max(highest, kinds_[indices_[i]]);
        }
        if (lowest == highest) return false;
        const std::uint32_t mid =
            partition(r, [&](std::uint32_t p) { return kinds_[p] == lowest; }).mid;
        left = {r.begin, mid};
        right = {mid, r.end};
        measure(left);
        measure(right);
        return true;
    }

    // Whether r may be a leaf: at most max_leaf_ leaf tests (and 255 primitives).
    bool fits_leaf(const Range& r) const {
        if (r.size() > std::min(255u, max_leaf_ * block_size_)) return false;
        std::uint32_t n = 0;
        for (std::uint32_t i = r.begin; i < r.end; ++i) n += blocked(indices_[i]);
        return r.size() - n + (n + block_size_ - 1) / block_size_ <= max_leaf_;
    }

    std::uint32_t blocked(std::uint32_t p) const {
        return kinds_.empty() || kinds_[p] != 0 ? 1 : 0;
    }
    // Leaf tests for n primitives of which `blocked` are of kind 1.
    float tests(std::uint32_t n, std::uint32_t blocked) const {
        return shape_cost_ * float(n - blocked) + float((blocked + block_size_ - 1) / block_size_);
    }

    static int bin_of(Float4 centroid, int axis, float lo, float scale, int bins) {
        const float f = (centroid[axis] - lo) * scale;
        // NaN and negative go to the first bin, anything past the end to the last; the float is
        // compared before the cast, which would be undefined out of range.
        if (!(f > 0)) return 0;
        return f < float(bins - 1) ? int(f) : bins - 1;
    }

    using Bins = std::array<Bin, kMaxBins>;
    using AxisBins = std::array<Bins, 3>;

    // Where the bins of each axis lie: `count` bins over the centroids' extent on that axis. An
    // axis whose extent is zero (or not finite) has no candidates. Where the centroids coincide,
    // the boxes' lower corners are binned instead (by_corner): concentric shapes whose boxes
    // differ, such as a jack's three crossed cylinders, can still be told apart.
    struct Binning {
        int count = 0;
        bool by_corner = false;
        bool used[3] = {};
        float lo[3] = {}, scale[3] = {};
    };

    Float4 key(std::uint32_t p, const Binning& g) const {
        return g.by_corner ? boxes_[p].lo : centroids_[p];
    }

    // Sets g's axes over the extent of `points`; false when no axis has one.
    static bool place_bins(const Box4& points, Binning& g) {
        bool any = false;
        for (int a = 0; a < 3; ++a) {
            const float extent = points.hi[a] - points.lo[a];
            g.used[a] = extent > 0 && std::isfinite(extent);
            g.lo[a] = points.lo[a];
            g.scale[a] = g.used[a] ? float(g.count) / extent : 0;
            any = any || g.used[a];
        }
        return any;
    }

    static void clear_bins(AxisBins& bins, int count) {
        for (Bins& axis_bins : bins)
            for (int k = 0; k < count; ++k) axis_bins[std::size_t(k)] = Bin::empty();
    }

    // Adds `from`'s bins to `to`'s. A bin's box is the same whatever order its boxes are taken
    // in (grow() skips NaN; only a zero's sign could differ, which no area sees), so the tree is.
    static void merge_bins(AxisBins& to, const AxisBins& from, int count) {
        for (int a = 0; a < 3; ++a)
            for (int k = 0; k < count; ++k) {
                Bin& bin = to[std::size_t(a)][std::size_t(k)];
                const Bin& part = from[std::size_t(a)][std::size_t(k)];
                bin.bounds.grow(part.bounds);
                bin.count += part.count;
                bin.blocked += part.blocked;
            }
    }

    void bin_block(std::uint32_t b, std::uint32_t e, const Binning& g, AxisBins& bins) const {
        // bin_of on all three axes at once: the same operations lane by lane.
        const Float4 lo{g.lo[0], g.lo[1], g.lo[2], 0};
        const Float4 scale{g.scale[0], g.scale[1], g.scale[2], 0};
        const Float4 last = splat(float(g.count - 1));
        const auto add = [&](std::uint32_t i, AxisBins& to) {
            const std::uint32_t p = indices_[i];
            const std::uint32_t is_blocked = blocked(p);
            const Float4 f = (key(p, g) - lo) * scale;
            const Float4 positive = f > 0 ? f : splat(0);  // NaN too goes to the first bin
            const Int4 index = __builtin_convertvector(positive < last ? positive : last, Int4);
            for (int axis = 0; axis < 3; ++axis) {
                if (!g.used[axis]) continue;
                Bin& bin = to[std::size_t(axis)][std::size_t(index[axis])];
                bin.bounds.grow(boxes_[p]);
                ++bin.count;
                bin.blocked += is_blocked;
            }
        };
        std::uint32_t i = b;
        // Neighbouring primitives often fall in the same bins, and the updates of one bin wait on
        // each other through memory: a second set of bins takes every other primitive.
        if (e - b >= kTwoBinSets) {
            AxisBins other;
            clear_bins(other, g.count);
            for (; i + 1 < e; i += 2) {
                add(i, bins);
                add(i + 1, other);
            }
            merge_bins(bins, other, g.count);
        }
        for (; i < e; ++i) add(i, bins);
    }

    // Partitions r by the cheapest SAH plane of the three axes (in axis order at equal cost;
    // Embree's binned builder tries all three too) and fills in both halves, setting `axis`, or
    // returns false when a leaf is cheaper or no axis has an extent.
    bool sah_split(const Range& r, Range& left, Range& right, int& axis) {
        Binning g;
        // Small ranges need fewer candidates: most bins would be empty.
        g.count = std::min(bins_, std::max(4, 2 * int(r.size())));
        if (!place_bins(r.centroids, g)) {
            Box4 corners = Box4::empty();
            for (std::uint32_t i = r.begin; i < r.end; ++i) corners.grow(boxes_[indices_[i]].lo);
            g.by_corner = true;
            if (!place_bins(corners, g)) return false;
        }
        AxisBins bins;
        clear_bins(bins, g.count);
        if (r.size() < kParallelRange) {
            bin_block(r.begin, r.end, g, bins);
        } else {
            std::vector<AxisBins> partial(blocks_of(r.size()));
            for_blocks(r.begin, r.end, [&](std::uint32_t b, std::uint32_t e, std::uint32_t k) {
                clear_bins(partial[k], g.count);
                bin_block(b, e, g, partial[k]);
            });
            for (const AxisBins& p : partial) merge_bins(bins, p, g.count);
        }
        // cost(split after bin k) = traversal + (A_left T_left + A_right T_right) / A_node, T the
        // leaf tests of a side, swept from both ends so that each candidate costs O(1). Only
        // splits after a bin that holds something are costed: after an empty bin the sides, and
        // so the cost, are those of the split before it, which comes first and wins the tie; a
        // split with nothing on the left costs a leaf's tests plus a traversal, never chosen.
        const int count = g.count;
        float best_cost = kInfinity;
        int best = -1;
        std::uint32_t range_blocked = 0;
        for (int a = 0; a < 3; ++a) {
            if (!g.used[a]) continue;
            const Bins& axis_bins = bins[std::size_t(a)];
            std::array<int, kMaxBins> held;  // the bins that hold something, in order
            int m = 0;
            for (int k = 0; k < count; ++k)
                if (axis_bins[std::size_t(k)].count != 0) held[std::size_t(m++)] = k;
            // right_cost[k]: the bins after k.
            std::array<float, kMaxBins> right_cost;
            Box4 acc = Box4::empty();
            std::uint32_t n = 0, nb = 0;
            for (int i = m - 1; i >= 0; --i) {
                const Bin& bin = axis_bins[std::size_t(held[std::size_t(i)])];
                right_cost[std::size_t(held[std::size_t(i)])] = acc.area() * tests(n, nb);
                acc.grow(bin.bounds);
                n += bin.count;
                nb += bin.blocked;
            }
            range_blocked = nb;
            acc = Box4::empty();
            n = nb = 0;
            for (int i = 0; i < m; ++i) {
                const int k = held[std::size_t(i)];
                if (k == count - 1) break;
                const Bin& bin = axis_bins[std::size_t(k)];
                acc.grow(bin.bounds);
                n += bin.count;
                nb += bin.blocked;
                const float cost = acc.area() * tests(n, nb) + right_cost[std::size_t(k)];
                if (cost < best_cost) best_cost = cost, best = k, axis = a;
            }
        }
        const float area = r.bounds.area();
        const float leaf_cost = tests(r.size(), range_blocked);
        const float split_cost = traversal_cost_ + (area > 0 ? best_cost / area : 0);
        if (best < 0 || !(split_cost < leaf_cost)) return false;

        const float lo = g.lo[axis], scale = g.scale[axis];
        const Parts parts = partition(
            r, [&](std::uint32_t p) { return bin_of(key(p, g), axis, lo, scale, count) <= best; });
        left = {r.begin, parts.mid, Box4::empty(), parts.centroids[0]};
        right = {parts.mid, r.end, Box4::empty(), parts.centroids[1]};
        for (int k = 0; k < count; ++k)
            (k <= best ? left : right).bounds.grow(bins[std::size_t(axis)][std::size_t(k)].bounds);
        if (left.size() > 0 && right.size() > 0) return true;
        // Every centroid in one bin (rounding of the bin index): halve by count instead.
        median_split(r, axis, left, right);
        return true;
    }

    // The two parts of a partitioned range: where the right one starts, and the union of each
    // part's centroids (left, right).
    struct Parts {
        std::uint32_t mid;
        std::array<Box4, 2> centroids{Box4::empty(), Box4::empty()};
    };

    // Stable partition of r by `goes_left`, through scratch_. Large ranges count, then scatter,
    // in blocks: the same order as one pass.
    template <typename Pred>
    Parts partition(const Range& r, Pred&& goes_left) {
        Parts parts{r.begin};
        std::array<Box4, 2>& sides = parts.centroids;
        if (r.size() < kParallelRange) {
            // scratch_ is shared by concurrent tasks; each uses only its own range of it.
            std::uint32_t l = r.begin, g = r.begin;
            for (std::uint32_t i = r.begin; i < r.end; ++i) {
                const std::uint32_t p = indices_[i];
                const bool left = goes_left(p);
                (left ? indices_[l++] : scratch_[g++]) = p;
                sides[left ? 0 : 1].grow(centroids_[p]);
            }
            std::copy(scratch_.begin() + r.begin, scratch_.begin() + g, indices_.begin() + l);
            parts.mid = l;
            return parts;
        }
        std::vector<std::uint32_t> lefts(blocks_of(r.size()));
        for_blocks(r.begin, r.end, [&](std::uint32_t b, std::uint32_t e, std::uint32_t k) {
            std::uint32_t n = 0;
            for (std::uint32_t i = b; i < e; ++i) n += goes_left(indices_[i]) ? 1 : 0;
            lefts[k] = n;
        });
        std::vector<std::uint32_t> left_at(lefts.size()), right_at(lefts.size());
        std::uint32_t total_left = 0;
        for (std::size_t k = 0; k < lefts.size(); ++k)
            left_at[k] = total_left, total_left += lefts[k];
        const std::uint32_t mid = r.begin + total_left;
        for (std::size_t k = 0; k < lefts.size(); ++k) {
            right_at[k] = mid + std::uint32_t(k) * kBlock - left_at[k];
            left_at[k] += r.begin;
        }
        std::vector<std::array<Box4, 2>> block_sides(lefts.size());
        for_blocks(r.begin, r.end, [&](std::uint32_t b, std::uint32_t e, std::uint32_t k) {
            std::uint32_t l = left_at[k], g = right_at[k];
            std::array<Box4, 2> side{Box4::empty(), Box4::empty()};
            for (std::uint32_t i = b; i < e; ++i) {
                const std::uint32_t p = indices_[i];
                const bool left = goes_left(p);
                scratch_[left ? l++ : g++] = p;
                side[left ? 0 : 1].grow(centroids_[p]);
            }
            block_sides[k] = side;
        });
        // In block order: with NaN coordinates, min and max depend on the order taken in.
        for (const std::array<Box4, 2>& side : block_sides) {
            sides[0].grow(side[0]);
            sides[1].grow(side[1]);
        }
        for_blocks(r.begin, r.end, [&](std::uint32_t b, std::uint32_t e, std::uint32_t) {
            std::copy(scratch_.begin() + b, scratch_.begin() + e, indices_.begin() + b);
        });
        parts.mid = mid;
        return parts;
    }

    // Halves r by count, ordered along the axis; works whatever the centroids are.
    void median_split(const Range& r, int axis, Range& left, Range& right) {
        const std::uint32_t mid = r.begin + r.size() / 2;
        const auto first = indices_.begin();
        std::nth_element(first + r.begin, first + mid, first + r.end,
                         [&](std::uint32_t a, std::uint32_t b) {
                             // NaN compares false both ways, which nth_element tolerates only
                             // as "equal"; order it before every number to keep a strict order.
                             const float ca = centroids_[a][axis], cb = centroids_[b][axis];
                             if (std::isnan(ca) || std::isnan(cb))
                                 return std::isnan(ca) && !std::isnan(cb);
                             return ca < cb;
                         });
        left = {r.begin, mid};
        right = {mid, r.end};
        measure(left);
        measure(right);
    }

    LargeVector<std::uint32_t>& indices_;
    std::span<const std::uint8_t> kinds_;
    LargeVector<Box4> boxes_;
    LargeVector<Float4> centroids_;
    LargeVector<std::uint32_t> scratch_;
    std::uint32_t max_leaf_ = 4;
    int bins_ = 16;
    float traversal_cost_ = 0.5f;
    std::uint32_t block_size_ = 1;
    float shape_cost_ = 1;
};

std::size_t node_count(const Chunk& chunk) {
    std::size_t n = chunk.nodes.size();
    for (const Chunk::Remote& remote : chunk.remote) n += node_count(*remote.chunk);
    return n;
}

// Appends the chunk's nodes and then, in order, each remote chunk's, with second-child indices
// moved to their final places, and the range each chunk took.
void flatten(const Chunk& chunk, std::int32_t parent, Bvh& out) {
    const auto base = std::uint32_t(out.nodes.size());
    for (BvhNode node : chunk.nodes) {
        if (!node.is_leaf()) node.offset += base;
        out.nodes.push_back(node);
    }
    const auto self = std::int32_t(out.node_ranges.size());
    out.node_ranges.push_back({base, std::uint32_t(out.nodes.size()), parent});
    for (const Chunk::Remote& remote : chunk.remote) {
        out.nodes[base + remote.node].offset = std::uint32_t(out.nodes.size());
        flatten(*remote.chunk, self, out);
    }
}

}  // namespace

Bvh build_bvh(std::span<const Bounds3> bounds, const BvhBuildOptions& options,
              std::span<const std::uint8_t> kinds) {
    Bvh bvh;
    if (bounds.empty()) return bvh;
    assert(bounds.size() <= 0xffffffffu);
    const auto n = std::uint32_t(bounds.size());
    bvh.primitive_indices.resize(n);
    assert(kinds.empty() || kinds.size() == bounds.size());
    Builder builder(bounds, options, kinds, bvh);
    Chunk chunk;
    builder.build(builder.root(), 0, chunk);
    if (chunk.remote.empty()) {
        bvh.nodes = std::move(chunk.nodes);
        bvh.nodes.shrink_to_fit();
        bvh.node_ranges.push_back({0, std::uint32_t(bvh.nodes.size()), -1});
    } else {
        bvh.nodes.reserve(node_count(chunk));
        flatten(chunk, -1, bvh);
    }
    return bvh;
}

}  // namespace glint
