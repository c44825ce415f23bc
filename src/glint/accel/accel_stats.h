// What an acceleration structure is made of, for `glint info`: its nodes, leaves, depth, how
// full its leaves are, its SAH cost and its memory. Every structure reports the same fields; a
// grid's cells are its leaves.
#pragma once

#include <cstddef>
#include <string_view>

#include "glint/math/bounds.h"

namespace glint {

// The constants of sah_cost below, the same for every structure so that their costs compare:
// one node step (a box test, a kd split, a grid cell entered) and one primitive test each cost 1.
// The structures' own builders weigh them differently (bvh.h, kdtree_aggregate.h).
inline constexpr double kSahTraversalCost = 1;
inline constexpr double kSahIntersectionCost = 1;

struct AccelStats {
    // False when the structure does not show its insides (Embree): only memory_bytes and
    // unbounded are meaningful then.
    bool available = true;
    std::size_t interior_nodes = 0;  // a wide BVH's nodes of up to eight children count once
    std::size_t leaves = 0;          // a grid's cells
    std::size_t empty_leaves = 0;    // leaves (cells) that hold no primitive
    int max_depth = 0;               // of the deepest leaf; the root is at depth 0
    double mean_leaf_depth = 0;      // over all leaves
    // Primitive references per non-empty leaf: a mesh's triangles each count, and a primitive
    // that a kd-tree or grid lists in several leaves counts in each.
    std::size_t min_leaf_size = 0, max_leaf_size = 0;
    double mean_leaf_size = 0;
    std::size_t references = 0;  // summed over the leaves
    std::size_t unbounded = 0;   // primitives (planes) tested beside the structure by every ray
    // The surface area heuristic (Goldsmith and Salmon 1987; MacDonald and Booth 1990): the
    // expected cost of a ray that enters the root box, when the chance that it enters a node is
    // the node's surface area over the root's:
    //   Σ_interior C_trav A(n)/A(root) + Σ_leaves C_isect |leaf| A(leaf)/A(root)
    //   + C_isect · unbounded
    // A grid's cells are entered by the 3D-DDA, each a step: a cell adds C_trav A(cell)/A(root)
    // too. With a root of zero area (everything in one point) every node counts as entered.
    double sah_cost = 0;
    std::size_t memory_bytes = 0;  // Aggregate::memory_bytes()
};

// Gathers the figures node by node; the structure walks itself and reports each node with its
// box and depth.
class AccelStatsTally {
public:
    explicit AccelStatsTally(const Bounds3& root) : root_area_(area_of(root)) {}

    void interior(const Bounds3& box);
    void leaf(const Bounds3& box, int depth, std::size_t references);
    // A grid cell: a leaf at depth 0 that the traversal enters by a step of its own.
    void cell(const Bounds3& box, std::size_t references);

    // The figures so far, with the unbounded primitives and the memory added.
    AccelStats finish(std::size_t unbounded, std::size_t memory_bytes) const;

private:
    static double area_of(const Bounds3& box);
    // The chance that a ray entering the root enters the box.
    double chance(const Bounds3& box) const;

    double root_area_;
    AccelStats stats_;
    double depth_sum_ = 0;
    double sah_ = 0;
};

}  // namespace glint
