// Collapsing the binary BVH into four-wide nodes.
#include "glint/geometry/bvh4.h"

#include <array>
#include <cassert>

namespace glint {

namespace {

class Collapser {
public:
    Collapser(const std::vector<BvhNode>& binary, std::vector<Bvh4Node>& wide)
        : binary_(binary), wide_(wide) {}

    // Fills wide_[index] from the binary subtree at `root`, then its descendants. The interior
    // children of a node are placed side by side, so that a traversal that visits several of them
    // touches neighbouring cache lines.
    void collapse(std::uint32_t root, std::uint32_t index) {
        std::array<std::uint32_t, 4> slot{};
        int n = 0;
        if (binary_[root].is_leaf()) {
            slot[n++] = root;
        } else {
            slot[n++] = root + 1;
            slot[n++] = binary_[root].offset;
            while (n < 4 && open_largest(slot, n)) ++n;
        }
        auto next = std::uint32_t(wide_.size());
        for (int k = 0; k < n; ++k) next += binary_[slot[std::size_t(k)]].is_leaf() ? 0 : 1;
        const auto first_child = std::uint32_t(wide_.size());
        wide_.resize(next);
        Bvh4Node& node = wide_[index];
        next = first_child;
        for (int k = 0; k < 4; ++k) {
            const Bounds3 b = k < n ? binary_[slot[std::size_t(k)]].bounds : Bounds3{};
            node.planes[0][k] = b.min.x, node.planes[1][k] = b.min.y, node.planes[2][k] = b.min.z;
            node.planes[3][k] = b.max.x, node.planes[4][k] = b.max.y, node.planes[5][k] = b.max.z;
            node.child[k] = kBvh4Leaf;
            node.count[k] = 0;
            if (k >= n) continue;
            const BvhNode& child = binary_[slot[std::size_t(k)]];
            if (child.is_leaf()) {
                assert(child.offset < kBvh4Leaf && child.count <= 255);
                node.child[k] = kBvh4Leaf | child.offset;
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
    // Replaces the interior child of largest surface area (the lowest slot at equal area) by its
    // two children, in place; false when every child is a leaf.
    bool open_largest(std::array<std::uint32_t, 4>& slot, int n) const {
        int best = -1;
        float best_area = -1;
        for (int k = 0; k < n; ++k) {
            const BvhNode& node = binary_[slot[std::size_t(k)]];
            if (node.is_leaf()) continue;
            const float area = node.bounds.surface_area();
            if (best < 0 || area > best_area) best = k, best_area = area;
        }
        if (best < 0) return false;
        const std::uint32_t opened = slot[std::size_t(best)];
        for (int k = n; k > best + 1; --k) slot[std::size_t(k)] = slot[std::size_t(k - 1)];
        slot[std::size_t(best)] = opened + 1;
        slot[std::size_t(best + 1)] = binary_[opened].offset;
        return true;
    }

    const std::vector<BvhNode>& binary_;
    std::vector<Bvh4Node>& wide_;
};

}  // namespace

Bvh4 collapse_to_bvh4(Bvh binary) {
    Bvh4 wide;
    if (binary.nodes.empty()) return wide;
    assert(binary.primitive_indices.size() < kBvh4Leaf);
    wide.root_bounds = binary.nodes[0].bounds;
    // Each wide node opens at least one interior binary node, and half the nodes are leaves.
    wide.nodes.reserve(binary.nodes.size() / 2 + 1);
    wide.nodes.resize(1);
    Collapser(binary.nodes, wide.nodes).collapse(0, 0);
    wide.nodes.shrink_to_fit();
    wide.primitive_indices = std::move(binary.primitive_indices);
    return wide;
}

Bvh4 build_bvh4(std::span<const Bounds3> bounds, const BvhBuildOptions& options) {
    return collapse_to_bvh4(build_bvh(bounds, options));
}

}  // namespace glint
