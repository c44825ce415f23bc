// Collapsing the binary BVH into wide nodes, and packing leaves of triangles and spheres into
// blocks.
#include "glint/accel/wide_bvh.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_group.h>

#include <algorithm>
#include <array>
#include <cassert>
#include <vector>

namespace glint {

namespace {

// Which interior binary nodes become wide nodes, chosen to minimise the summed surface area of
// the wide nodes: the SAH cost of their tests (every leaf is tested under some wide node however
// the tree is cut, so the leaves' cost is the same for every choice). Dynamic programming over
// the binary tree (Ylitie, Karras and Laine 2017, "Efficient Incoherent Ray Traversal on GPUs
// Through Compressed Wide BVHs", section 4.1, without its leaf merging).
class CollapsePlan {
public:
    // Solved from the leaves up: each of the build's node ranges after the ranges below it (in
    // parallel, as tasks), its own nodes from its end (children come after their parents).
    explicit CollapsePlan(const Bvh& binary)
        : binary_(binary.nodes),
          cost_(binary.nodes.size() * kWideBvhWidth),
          choice_(binary.nodes.size() * kWideBvhWidth) {
        const std::vector<BvhNodeRange>& ranges = binary.node_ranges;
        if (ranges.empty()) {
            solve_nodes(0, binary.nodes.size());
            return;
        }
        std::vector<std::vector<std::uint32_t>> below(ranges.size());
        for (std::uint32_t i = 1; i < ranges.size(); ++i)
            below[std::size_t(ranges[i].parent)].push_back(i);
        solve_range(ranges, below, 0);
    }

    // The children of the wide node made of binary node `n`: its subtree cut at the nodes and
    // leaves the plan keeps whole, in depth-first order.
    void children(std::uint32_t n, std::array<std::uint32_t, kWideBvhWidth>& slot,
                  int& count) const {
        const int j = split(n, 1);
        emit(n + 1, j, slot, count);
        emit(binary_[n].offset, kWideBvhWidth - j, slot, count);
    }

private:
    void solve_range(const std::vector<BvhNodeRange>& ranges,
                     const std::vector<std::vector<std::uint32_t>>& below, std::uint32_t r) {
        tbb::task_group group;
        for (const std::uint32_t b : below[r]) group.run([&, b] { solve_range(ranges, below, b); });
        group.wait();
        solve_nodes(ranges[r].begin, ranges[r].end);
    }

    void solve_nodes(std::size_t begin, std::size_t end) {
        for (std::size_t n = end; n-- > begin;) {
            const BvhNode& node = binary_[n];
            if (node.is_leaf()) {
                for (int k = 1; k <= kWideBvhWidth; ++k) set(n, k, 0, 0, true);
                continue;
            }
            const std::size_t left = n + 1, right = node.offset;
            // dissolved[k]: the least cost of spreading the children over k slots.
            double dissolved[kWideBvhWidth + 1];
            int best_split[kWideBvhWidth + 1];
            for (int k = 2; k <= kWideBvhWidth; ++k) {
                dissolved[k] = kInfinity;
                best_split[k] = 1;
                for (int j = 1; j < k; ++j) {
                    const double c = cost(left, j) + cost(right, k - j);
                    if (c < dissolved[k]) dissolved[k] = c, best_split[k] = j;
                }
            }
            const double as_node = double(node.bounds.surface_area()) + dissolved[kWideBvhWidth];
            set(n, 1, as_node, best_split[kWideBvhWidth], true);
            for (int k = 2; k <= kWideBvhWidth; ++k) {
                // Dissolving at equal cost makes fewer nodes.
                if (dissolved[k] <= as_node) {
                    set(n, k, dissolved[k], best_split[k], false);
                } else {
                    set(n, k, as_node, best_split[kWideBvhWidth], true);
                }
            }
        }
    }

    std::size_t index(std::size_t n, int k) const { return n * kWideBvhWidth + std::size_t(k - 1); }
    double cost(std::size_t n, int k) const { return cost_[index(n, k)]; }
    int split(std::size_t n, int k) const { return choice_[index(n, k)] & kSplit; }
    bool wide(std::size_t n, int k) const { return (choice_[index(n, k)] & kWide) != 0; }
    void set(std::size_t n, int k, double cost, int split, bool wide) {
        cost_[index(n, k)] = float(cost);
        choice_[index(n, k)] = std::uint8_t(split | (wide ? kWide : 0));
    }
    // Binary node n given k slots: one slot if it stays whole, else its children share them.
    void emit(std::uint32_t n, int k, std::array<std::uint32_t, kWideBvhWidth>& slot,
              int& count) const {
        if (binary_[n].is_leaf() || wide(n, k)) {
            slot[std::size_t(count++)] = n;
            return;
        }
        const int j = split(n, k);
        emit(n + 1, j, slot, count);
        emit(binary_[n].offset, k - j, slot, count);
    }

    // A choice: the slots given to the first child when n is split (low bits), and whether n
    // stays whole given k slots.
    static constexpr std::uint8_t kSplit = 0x0f;
    static constexpr std::uint8_t kWide = 0x80;

    const LargeVector<BvhNode>& binary_;
    // [n][k - 1]: the least area of wide nodes when n takes k slots (kept in float, 32 bytes a
    // node, and summed in double), and the choice that reaches it.
    LargeVector<float> cost_;
    LargeVector<std::uint8_t> choice_;
};

class Collapser {
public:
    Collapser(const Bvh& binary, LargeVector<WideBvhNode>& wide)
        : binary_(binary.nodes), wide_(wide), plan_(binary) {}

    // Fills wide_[index] from the binary subtree at `root` (a lone leaf becomes the only child),
    // then its descendants. The interior children of a node are placed side by side, so that a
    // traversal that visits several of them touches neighbouring cache lines.
    void collapse(std::uint32_t root, std::uint32_t index) {
        std::array<std::uint32_t, kWideBvhWidth> slot{};
        int n = 0;
        if (binary_[root].is_leaf()) {
            slot[std::size_t(n++)] = root;
        } else {
            plan_.children(root, slot, n);
        }
        auto next = std::uint32_t(wide_.size());
        for (int k = 0; k < n; ++k) next += binary_[slot[std::size_t(k)]].is_leaf() ? 0 : 1;
        const auto first_child = std::uint32_t(wide_.size());
        wide_.resize(next);
        WideBvhNode& node = wide_[index];
        next = first_child;
        for (int k = 0; k < kWideBvhWidth; ++k) {
            const Bounds3 b = k < n ? binary_[slot[std::size_t(k)]].bounds : Bounds3{};
            node.planes[0][k] = b.min.x, node.planes[1][k] = b.min.y, node.planes[2][k] = b.min.z;
            node.planes[3][k] = b.max.x, node.planes[4][k] = b.max.y, node.planes[5][k] = b.max.z;
            node.child[k] = kWideLeaf;
            node.count[k] = 0;
            if (k >= n) continue;
            const BvhNode& child = binary_[slot[std::size_t(k)]];
            if (child.is_leaf()) {
                assert(child.offset <= kWideLeafIndex && child.count <= 255);
                node.child[k] = kWideLeaf | child.offset;
                node.count[k] = std::uint8_t(child.count);
            } else {
                node.child[k] = next++;
            }
        }
        for (int k = 0; k < n; ++k) {
            if (binary_[slot[std::size_t(k)]].is_leaf()) continue;
            collapse(slot[std::size_t(k)], wide_[index].child[k]);  // wide_ may have moved
        }
    }

private:
    const LargeVector<BvhNode>& binary_;
    LargeVector<WideBvhNode>& wide_;
    CollapsePlan plan_;
};

}  // namespace

WideBvh collapse_to_wide_bvh(Bvh binary) {
    WideBvh wide;
    if (binary.nodes.empty()) return wide;
    assert(binary.primitive_indices.size() <= kWideBvhMaxPrimitives);
    wide.root_bounds = binary.nodes[0].bounds;
    // Each wide node opens at least one interior binary node, and half the nodes are leaves.
    wide.nodes.reserve(binary.nodes.size() / 2 + 1);
    wide.nodes.resize(1);
    Collapser(binary, wide.nodes).collapse(0, 0);
    wide.nodes.shrink_to_fit();
    wide.primitive_indices = std::move(binary.primitive_indices);
    return wide;
}

WideBvh build_wide_bvh(std::span<const Bounds3> bounds, const BvhBuildOptions& options,
                       std::span<const std::uint8_t> kinds) {
    return collapse_to_wide_bvh(build_bvh(bounds, options, kinds));
}

namespace {

enum class LeafKind : std::uint8_t { kept, triangles, spheres };

// A leaf child of a wide node: where its primitives are in primitive_indices, what they turned
// out to be, and where its blocks (or kept indices) start.
struct LeafSlot {
    WideBvhNode* node;
    int k;
    std::uint32_t first, count;
    LeafKind kind = LeafKind::kept;
    std::uint32_t start = 0;
};

// The kind of every primitive of the leaf (kBlockTriangle, kBlockSphere or another), or
// kKeptAsIs when they differ.
constexpr std::uint8_t kKeptAsIs = 0;
std::uint8_t leaf_kind_of(std::span<const std::uint32_t> leaf,
                          std::span<const std::uint8_t> kinds) {
    if (kinds.empty()) return kBlockTriangle;
    const std::uint8_t first = kinds[leaf[0]];
    for (const std::uint32_t i : leaf)
        if (kinds[i] != first) return kKeptAsIs;
    return first;
}

// item(i) for each of the leaf's primitives, set into the lanes of its blocks in ascending id
// (so that the lowest lane at equal t is the lowest id). Gathered on the stack, and straight into
// the blocks: an array of every primitive's item, 40 bytes a triangle, was a tenth of a large
// mesh's build in fresh pages alone.
template <typename Item, typename Block, typename SetLane>
void fill_blocks(std::span<const std::uint32_t> leaf,
                 const std::function<Item(std::uint32_t)>& item, Block* blocks,
                 SetLane&& set_lane) {
    // The largest leaf of kWideBvhTriangleBuildOptions (four blocks).
    constexpr auto kOnStack = std::size_t(kWideBvhTriangleBuildOptions.max_leaf_size *
                                          kWideBvhTriangleBuildOptions.block_size);
    std::array<Item, kOnStack> on_stack;
    std::vector<Item> on_heap;
    Item* items = on_stack.data();
    if (leaf.size() > kOnStack) {
        on_heap.resize(leaf.size());
        items = on_heap.data();
    }
    for (std::size_t j = 0; j < leaf.size(); ++j) items[j] = item(leaf[j]);
    std::sort(items, items + leaf.size(), [](const Item& a, const Item& b) { return a.id < b.id; });
    for (std::size_t j = 0; j < leaf.size(); ++j) set_lane(blocks[j / 4], int(j % 4), items[j]);
}

std::uint32_t blocks_for(std::uint32_t count) { return (count + 3) / 4; }

}  // namespace

void pack_block_leaves(WideBvh& bvh, std::span<const std::uint8_t> kinds,
                       const std::function<BlockTriangle(std::uint32_t)>& triangle,
                       const std::function<BlockSphere(std::uint32_t)>& sphere) {
    std::vector<LeafSlot> leaves;
    for (WideBvhNode& node : bvh.nodes)
        for (int k = 0; k < kWideBvhWidth; ++k) {
            if (!node.is_leaf(k) || node.count[k] == 0) continue;
            assert((node.child[k] & kWideLeafKind) == kWidePrimitiveLeaf);
            leaves.push_back({.node = &node,
                              .k = k,
                              .first = node.child[k] & kWideLeafIndex,
                              .count = node.count[k]});
        }
    const auto leaf_of = [&](const LeafSlot& l) {
        return std::span<const std::uint32_t>(bvh.primitive_indices.data() + l.first, l.count);
    };
    // Each leaf's kind, from its primitives' kinds alone.
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, leaves.size(), 256),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                          for (std::size_t i = r.begin(); i != r.end(); ++i) {
                              LeafSlot& l = leaves[i];
                              const std::uint8_t kind = leaf_kind_of(leaf_of(l), kinds);
                              l.kind = kind == kBlockTriangle && triangle ? LeafKind::triangles
                                       : kind == kBlockSphere && sphere   ? LeafKind::spheres
                                                                          : LeafKind::kept;
                          }
                      });
    // Where each leaf's blocks (or kept indices) start, in the leaves' order.
    std::uint32_t triangle_blocks = 0, sphere_blocks = 0, kept = 0;
    for (LeafSlot& l : leaves) {
        std::uint32_t tag = kWidePrimitiveLeaf;
        std::uint32_t* next = &kept;
        if (l.kind == LeafKind::triangles) {
            tag = kWideTriangleLeaf;
            next = &triangle_blocks;
        } else if (l.kind == LeafKind::spheres) {
            tag = kWideSphereLeaf;
            next = &sphere_blocks;
        }
        l.start = *next;
        *next += l.kind == LeafKind::kept ? l.count : blocks_for(l.count);
        l.node->child[l.k] = kWideLeaf | tag | l.start;
        if (l.kind != LeafKind::kept) l.node->count[l.k] = std::uint8_t(blocks_for(l.count));
    }
    assert(triangle_blocks <= kWideBvhMaxPrimitives && sphere_blocks <= kWideBvhMaxPrimitives);
    LargeVector<std::uint32_t> kept_indices(kept);
    bvh.blocks.assign(triangle_blocks, empty_triangle_block());
    bvh.sphere_blocks.assign(sphere_blocks, empty_sphere_block());
    const auto fill = [&](const LeafSlot& l) {
        switch (l.kind) {
            case LeafKind::triangles:
                fill_blocks(leaf_of(l), triangle, bvh.blocks.data() + l.start,
                            [](TriangleBlock& block, int lane, const BlockTriangle& t) {
                                set_block_lane(block, lane, t.v0, t.v1, t.v2, t.id);
                            });
                break;
            case LeafKind::spheres:
                fill_blocks(leaf_of(l), sphere, bvh.sphere_blocks.data() + l.start,
                            [](SphereBlock& block, int lane, const BlockSphere& s) {
                                set_sphere_lane(block, lane, s.sphere, s.id);
                            });
                break;
            case LeafKind::kept:
                std::copy_n(bvh.primitive_indices.data() + l.first, l.count,
                            kept_indices.data() + l.start);
                break;
        }
    };
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, leaves.size(), 256),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                          for (std::size_t i = r.begin(); i != r.end(); ++i) fill(leaves[i]);
                      });
    bvh.primitive_indices = std::move(kept_indices);
}

}  // namespace glint
