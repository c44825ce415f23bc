// The kd-tree (an axis-aligned BSP tree): SAH-built splitting planes over the bounded primitives
// in 8-byte nodes, walked front to back with a small stack of t intervals.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "glint/accel/aggregate.h"
#include "glint/accel/primitive_refs.h"

namespace glint {

// Deeper trees are never built, so a traversal stack of this many entries cannot overflow.
inline constexpr int kKdMaxDepth = 64;

// pbrt-v3's KdAccelNode: a split plane or a leaf in 8 bytes. An interior node's child below the
// plane is the next node in the array; the one above is at above_child().
struct KdNode {
    // Interior: the split position's float bits. Leaf: the primitive itself when it holds one,
    // else the offset of its first entry in the leaf primitive list.
    std::uint32_t payload = 0;
    // Low two bits: the split axis (0, 1, 2), or 3 for a leaf. High 30 bits: the above child's
    // index (interior) or the number of primitives (leaf).
    std::uint32_t bits = 3;

    static KdNode interior(int axis, float split) {
        return {std::bit_cast<std::uint32_t>(split), std::uint32_t(axis)};
    }
    static KdNode leaf(std::uint32_t count, std::uint32_t payload) {
        return {payload, (count << 2) | 3u};
    }

    bool is_leaf() const { return (bits & 3u) == 3u; }
    int axis() const { return int(bits & 3u); }
    float split() const { return std::bit_cast<float>(payload); }
    std::uint32_t above_child() const { return bits >> 2; }
    std::uint32_t primitive_count() const { return bits >> 2; }
    void set_above_child(std::uint32_t index) { bits = (index << 2) | (bits & 3u); }
};
static_assert(sizeof(KdNode) == 8);

// SAH costs and limits; the defaults are pbrt-v3's (KdTreeAccel).
struct KdBuildOptions {
    float intersection_cost = 80;  // cost of one primitive test relative to...
    float traversal_cost = 1;      // ...one interior node step
    float empty_bonus = 0.5f;      // share of the cost saved by a split with an empty side
    int max_leaf_size = 1;         // a node with this many primitives or fewer is a leaf
    // Below 0: 8 + 1.3 log2(N), pbrt's rule. Always capped at kKdMaxDepth - 1.
    int max_depth = -1;
    // Leaves stop being split once they hold this many references per bounded primitive (plus
    // a constant); a safety net for scenes where splitting duplicates nearly every primitive.
    float max_references_per_primitive = 32;
};

// The kd-tree aggregate.
//
// Build: SAH over every candidate plane of all three axes (the primitives' bound edges), swept
// over event lists sorted once at the root and kept sorted by stable partitioning (Wald and
// Havran 2006, "On building fast kd-Trees for Ray Tracing, and on doing that in O(N log N)",
// without the clipping of primitives to the node: a primitive straddling a plane is listed on
// both sides with its whole bounds, as in pbrt-v3, which any shape allows). Terminates by SAH
// (leaf cheaper than the best split three times on a path, pbrt's "bad refines"), by depth and
// by leaf size, so coincident primitives end in one leaf instead of recursing.
//
// Exactness: primitives are classified against planes with their bounds grown by 8 ulps of the
// scene's largest coordinate (rounding_margin.h). A primitive listed only beyond a plane
// then has its hits farther along the ray than the plane plus that margin, which covers the
// rounding of t at the plane and in the shapes: so once the nearest hit so far lies before the
// next node's t interval, no later node can hold a nearer or equally near hit. At equal t the
// lower primitive index wins (nearer()), as in every aggregate.
class KdTreeAggregate final : public Aggregate {
public:
    explicit KdTreeAggregate(std::span<const Primitive> primitives,
                             const KdBuildOptions& options = {});

    Bounds3 bounds() const override { return bounds_; }
    std::size_t memory_bytes() const override;
    AccelStats statistics() const override;

    // nodes()[0] is the root; empty when there are no bounded primitives.
    std::span<const KdNode> nodes() const { return nodes_; }
    // The primitives of a leaf, in increasing index.
    std::span<const std::uint32_t> leaf_primitives(const KdNode& leaf) const {
        if (leaf.primitive_count() == 1) return {&leaf.payload, 1};
        return std::span(leaf_primitives_).subspan(leaf.payload, leaf.primitive_count());
    }
    int depth() const { return depth_; }  // of the deepest leaf; the root is at depth 0
    // Leaf-primitive pairs in all (each bounded primitive counts once per leaf holding it).
    std::size_t reference_count() const;

private:
    std::optional<Hit> closest_hit(const Ray& ray, Interval t_range,
                                   std::uint32_t ray_mask) const override;
    bool any_hit(const Ray& ray, Interval t_range, std::uint32_t ray_mask) const override;

    template <typename VisitLeaf>
    void walk(const Ray& ray, Interval t_range, VisitLeaf&& visit_leaf) const;

    PrimitiveRefs refs_;   // what the cells or leaves list, by index
    Bounds3 bounds_;       // of the bounded primitives, as given
    Bounds3 tree_bounds_;  // the root's box: the grown bounds
    std::vector<KdNode> nodes_;
    std::vector<std::uint32_t> leaf_primitives_;  // reference indices of leaves with two or more
    std::vector<std::uint32_t> unbounded_;        // primitives with infinite bounds (planes)
    int depth_ = 0;
};

}  // namespace glint
