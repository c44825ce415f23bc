// The wide BVH that meshes and the scene-level structure trace: the binary SAH tree collapsed into
// nodes of four children whose boxes are stored side by side, so that one SIMD node test checks
// all four (Wald et al. 2008, "Getting Rid of Packets"; Embree's BVH4). Traversal is in
// bvh4_traversal.h.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "glint/geometry/bvh.h"
#include "glint/math/bounds.h"

namespace glint {

// A child reference with this bit set is a leaf: the rest is the index of its first entry in
// Bvh4::primitive_indices. Without it, the index of a node.
inline constexpr std::uint32_t kBvh4Leaf = 0x80000000u;

// Two cache lines. An unused slot is an empty leaf with an empty box (min +inf, max -inf), so it
// is never entered, and visiting it (a NaN ray enters every box) does nothing.
struct alignas(64) Bvh4Node {
    // Child boxes as structure of arrays: planes[axis][slot] is the min side, planes[3 + axis]
    // the max side, so a node test loads one row per slab.
    float planes[6][4];
    std::uint32_t child[4];  // node index, or kBvh4Leaf | first primitive entry
    std::uint8_t count[4];   // primitives of a leaf child (0 for an unused slot); 0 for a node

    Bounds3 child_bounds(int slot) const {
        return {{planes[0][slot], planes[1][slot], planes[2][slot]},
                {planes[3][slot], planes[4][slot], planes[5][slot]}};
    }
    bool is_leaf(int slot) const { return (child[slot] & kBvh4Leaf) != 0; }
};
static_assert(sizeof(Bvh4Node) == 128, "two cache lines a node");

struct Bvh4 {
    std::vector<Bvh4Node> nodes;  // nodes[0] is the root; empty for no primitives
    // Leaves refer to ranges of this permutation of the primitives' indices.
    std::vector<std::uint32_t> primitive_indices;
    Bounds3 root_bounds;  // the union of every primitive's box

    Bounds3 bounds() const { return root_bounds; }
    std::size_t memory_bytes() const {
        return nodes.capacity() * sizeof(Bvh4Node) +
               primitive_indices.capacity() * sizeof(std::uint32_t);
    }
};

// The binary tree collapsed top down: each wide node takes a binary node's two children and keeps
// opening the one of largest surface area until it has four or all are leaves. Leaves, boxes and
// the primitive order stay as they were, so the wide tree's leaves are the binary tree's. The root
// is always a node (a lone leaf becomes the root's only child). Fewer than 2^31 primitives.
Bvh4 collapse_to_bvh4(Bvh binary);

// The wide tree's defaults: leaves of up to 8 primitives and a binary node costing as much as a
// primitive test. Measured against 4 and 1/2 (bench/README.md): as fast on meshes and SPD
// scenes, and a quarter fewer bytes per triangle.
inline constexpr BvhBuildOptions kBvh4BuildOptions{8, 16, 1.0f};

// build_bvh then collapse_to_bvh4: deterministic for any number of threads, like build_bvh.
Bvh4 build_bvh4(std::span<const Bounds3> bounds,
                const BvhBuildOptions& options = kBvh4BuildOptions);

}  // namespace glint
