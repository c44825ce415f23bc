// Collapsing the binary BVH into wide nodes, and packing leaves of triangles and spheres into
// blocks.
#include "glint/geometry/wide_bvh.h"

#include <algorithm>
#include <array>
#include <cassert>

namespace glint {

namespace {

class Collapser {
public:
    using Slots = std::array<std::uint32_t, kWideBvhWidth>;

    Collapser(const LargeVector<BvhNode>& binary, LargeVector<WideBvhNode>& wide)
        : binary_(binary), wide_(wide), leaves_(binary.size()) {
        // Children come after their parents in the binary array: count from the end.
        for (std::size_t i = binary.size(); i-- > 0;) {
            const BvhNode& node = binary[i];
            leaves_[i] = node.is_leaf() ? 1 : leaves_[i + 1] + leaves_[node.offset];
        }
    }

    // Fills wide_[index] from the binary subtree at `root`, then its descendants. The interior
    // children of a node are placed side by side, so that a traversal that visits several of them
    // touches neighbouring cache lines.
    void collapse(std::uint32_t root, std::uint32_t index) {
        Slots slot{};
        int n = 0;
        if (leaves_[root] <= std::uint32_t(kWideBvhWidth)) {
            gather_leaves(root, slot, n);  // a leaf alone, or a subtree that fits in one node
        } else {
            slot[n++] = root + 1;
            slot[n++] = binary_[root].offset;
            while (open_one(slot, n)) {
            }
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
    // Opens the interior child of largest surface area (the lowest slot at equal area) that can be
    // opened, in place: one of more than kWideBvhWidth leaves becomes its two children; one of
    // fewer becomes all its leaves, if they fit in the free slots. So a subtree of up to
    // kWideBvhWidth leaves is one full node, never a chain of nodes of two (which opening level by
    // level made of complete binary trees whose depth is not a multiple of three). False when none
    // can be opened.
    bool open_one(Slots& slot, int& n) const {
        int best = -1;
        float best_area = -1;
        for (int k = 0; k < n; ++k) {
            const std::uint32_t child = slot[std::size_t(k)];
            if (binary_[child].is_leaf()) continue;
            const std::uint32_t leaves = leaves_[child];
            const int grows = leaves > std::uint32_t(kWideBvhWidth) ? 1 : int(leaves) - 1;
            if (n + grows > kWideBvhWidth) continue;
            const float area = binary_[child].bounds.surface_area();
            if (best < 0 || area > best_area) best = k, best_area = area;
        }
        if (best < 0) return false;
        const std::uint32_t opened = slot[std::size_t(best)];
        Slots replacement{};
        int m = 0;
        if (leaves_[opened] > std::uint32_t(kWideBvhWidth)) {
            replacement[m++] = opened + 1;
            replacement[m++] = binary_[opened].offset;
        } else {
            gather_leaves(opened, replacement, m);
        }
        for (int k = n - 1; k > best; --k) slot[std::size_t(k + m - 1)] = slot[std::size_t(k)];
        for (int k = 0; k < m; ++k) slot[std::size_t(best + k)] = replacement[std::size_t(k)];
        n += m - 1;
        return true;
    }

    // Appends the leaves of the binary subtree at `node` to slot, in depth-first order.
    void gather_leaves(std::uint32_t node, Slots& slot, int& n) const {
        if (binary_[node].is_leaf()) {
            slot[std::size_t(n++)] = node;
            return;
        }
        gather_leaves(node + 1, slot, n);
        gather_leaves(binary_[node].offset, slot, n);
    }

    const LargeVector<BvhNode>& binary_;
    LargeVector<WideBvhNode>& wide_;
    std::vector<std::uint32_t> leaves_;  // of each binary node's subtree
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
    Collapser(binary.nodes, wide.nodes).collapse(0, 0);
    wide.nodes.shrink_to_fit();
    wide.primitive_indices = std::move(binary.primitive_indices);
    return wide;
}

WideBvh build_wide_bvh(std::span<const Bounds3> bounds, const BvhBuildOptions& options,
                       std::span<const std::uint8_t> kinds) {
    return collapse_to_wide_bvh(build_bvh(bounds, options, kinds));
}

namespace {

// The leaf's primitives as blocks of one kind, appended to `blocks`; false (and nothing appended)
// when one of them is not of that kind. Lanes run in ascending id. `items` is scratch space, kept
// from leaf to leaf.
template <typename Item, typename Block, typename EmptyBlock, typename SetLane>
bool pack_leaf(std::span<const std::uint32_t> leaf,
               const std::function<std::optional<Item>(std::uint32_t)>& item_of,
               std::vector<Item>& items, LargeVector<Block>& blocks, EmptyBlock&& empty_block,
               SetLane&& set_lane) {
    if (!item_of) return false;
    items.clear();
    for (const std::uint32_t p : leaf) {
        const auto item = item_of(p);
        if (!item) return false;
        items.push_back(*item);
    }
    std::sort(items.begin(), items.end(), [](const Item& a, const Item& b) { return a.id < b.id; });
    for (std::size_t i = 0; i < items.size(); ++i) {
        if (i % 4 == 0) blocks.push_back(empty_block());
        set_lane(blocks.back(), int(i % 4), items[i]);
    }
    return true;
}

}  // namespace

void pack_block_leaves(WideBvh& bvh,
                       const std::function<std::optional<BlockTriangle>(std::uint32_t)>& triangle,
                       const std::function<std::optional<BlockSphere>(std::uint32_t)>& sphere) {
    LargeVector<std::uint32_t> kept;  // primitive_indices of the leaves that stay as they are
    std::vector<BlockTriangle> triangles;
    std::vector<BlockSphere> spheres;
    for (WideBvhNode& node : bvh.nodes) {
        for (int k = 0; k < kWideBvhWidth; ++k) {
            if (!node.is_leaf(k) || node.count[k] == 0) continue;
            assert((node.child[k] & kWideLeafKind) == kWidePrimitiveLeaf);
            const std::span<const std::uint32_t> leaf(
                bvh.primitive_indices.data() + (node.child[k] & kWideLeafIndex), node.count[k]);
            const auto first_triangles = std::uint32_t(bvh.blocks.size());
            const auto first_spheres = std::uint32_t(bvh.sphere_blocks.size());
            if (pack_leaf(leaf, triangle, triangles, bvh.blocks, empty_triangle_block,
                          [](TriangleBlock& b, int lane, const BlockTriangle& t) {
                              set_block_lane(b, lane, t.v0, t.v1, t.v2, t.id);
                          })) {
                node.child[k] = kWideLeaf | kWideTriangleLeaf | first_triangles;
                node.count[k] = std::uint8_t(bvh.blocks.size() - first_triangles);
            } else if (pack_leaf(leaf, sphere, spheres, bvh.sphere_blocks, empty_sphere_block,
                                 [](SphereBlock& b, int lane, const BlockSphere& s) {
                                     set_sphere_lane(b, lane, s.sphere, s.id);
                                 })) {
                node.child[k] = kWideLeaf | kWideSphereLeaf | first_spheres;
                node.count[k] = std::uint8_t(bvh.sphere_blocks.size() - first_spheres);
            } else {
                node.child[k] = kWideLeaf | kWidePrimitiveLeaf | std::uint32_t(kept.size());
                kept.insert(kept.end(), leaf.begin(), leaf.end());
            }
            assert(bvh.blocks.size() <= kWideBvhMaxPrimitives &&
                   bvh.sphere_blocks.size() <= kWideBvhMaxPrimitives);
        }
    }
    kept.shrink_to_fit();
    bvh.primitive_indices = std::move(kept);
    bvh.blocks.shrink_to_fit();
    bvh.sphere_blocks.shrink_to_fit();
}

}  // namespace glint
