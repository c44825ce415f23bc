// The wide BVH that meshes and the scene-level structure trace: the binary SAH tree collapsed into
// nodes of eight children whose boxes are stored side by side, so that one SIMD node test checks
// all eight (Wald et al. 2008, "Getting Rid of Packets"; Embree's BVH8, which it uses on AVX2
// CPUs). Traversal is in wide_bvh_traversal.h.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include "glint/accel/bvh.h"
#include "glint/geometry/sphere_block.h"
#include "glint/geometry/triangle_block.h"
#include "glint/math/bounds.h"
#include "glint/math/huge_page_allocator.h"

namespace glint {

// A child reference with this bit set is a leaf; without it, the index of a node.
inline constexpr std::uint32_t kWideLeaf = 0x80000000u;
// The two bits below say what a leaf holds, and so what its index (the low bits) and its count
// refer to: entries of WideBvh::primitive_indices, triangle blocks or sphere blocks.
inline constexpr std::uint32_t kWideLeafKind = 0x60000000u;
inline constexpr std::uint32_t kWidePrimitiveLeaf = 0;
inline constexpr std::uint32_t kWideTriangleLeaf = 0x20000000u;
inline constexpr std::uint32_t kWideSphereLeaf = 0x40000000u;
inline constexpr std::uint32_t kWideLeafIndex = 0x1fffffffu;
// Primitives (and blocks) a tree can index.
inline constexpr std::size_t kWideBvhMaxPrimitives = std::size_t(kWideLeafIndex);

// Children of a node: one AVX2 register holds a coordinate of all eight boxes.
inline constexpr int kWideBvhWidth = 8;

// Four cache lines. An unused slot is an empty leaf with an empty box (min +inf, max -inf), so it
// is never entered, and visiting it (a NaN ray enters every box) does nothing.
struct alignas(64) WideBvhNode {
    // Child boxes as structure of arrays: planes[axis][slot] is the min side, planes[3 + axis]
    // the max side, so a node test loads one row per slab.
    float planes[6][kWideBvhWidth];
    std::uint32_t child[kWideBvhWidth];  // node, or kWideLeaf | kind | index
    std::uint8_t count[kWideBvhWidth];   // primitives or blocks of a leaf child (0: unused slot)

    Bounds3 child_bounds(int slot) const {
        return {{planes[0][slot], planes[1][slot], planes[2][slot]},
                {planes[3][slot], planes[4][slot], planes[5][slot]}};
    }
    bool is_leaf(int slot) const { return (child[slot] & kWideLeaf) != 0; }
};
static_assert(sizeof(WideBvhNode) == 256, "four cache lines a node");

struct WideBvh {
    LargeVector<WideBvhNode> nodes;  // nodes[0] is the root; empty for no primitives
    // Leaves of primitives refer to ranges of this permutation of the primitives' indices.
    LargeVector<std::uint32_t> primitive_indices;
    // Leaves of triangles and of spheres refer to ranges of these (see pack_block_leaves).
    LargeVector<TriangleBlock> blocks;
    LargeVector<SphereBlock> sphere_blocks;
    Bounds3 root_bounds;  // the union of every primitive's box

    Bounds3 bounds() const { return root_bounds; }
    std::size_t memory_bytes() const {
        return nodes.capacity() * sizeof(WideBvhNode) +
               primitive_indices.capacity() * sizeof(std::uint32_t) +
               blocks.capacity() * sizeof(TriangleBlock) +
               sphere_blocks.capacity() * sizeof(SphereBlock);
    }
};

// The binary tree collapsed into wide nodes: of all the ways to make some of its interior nodes
// wide nodes of at most kWideBvhWidth children (the subtree below cut at the next wide nodes and
// leaves), the one whose wide nodes have the least summed surface area, the SAH cost of their
// tests (dynamic programming, Ylitie et al. 2017). Children are in depth-first order. Leaves,
// boxes and the primitive order stay as they were, so the wide tree's leaves are the binary
// tree's. The root is always a node (a lone leaf becomes the root's only child). At most
// kWideBvhMaxPrimitives primitives.
WideBvh collapse_to_wide_bvh(Bvh binary);

// The wide tree's defaults for primitives tested one by one: leaves of up to 8 and a binary node
// costing as much as a primitive test (bench/README.md).
inline constexpr BvhBuildOptions kWideBvhBuildOptions{8, 16, 1.0f};
// For triangles and spheres, which leaves test four at a time (pack_block_leaves): SAH counts them
// in blocks of four (and shapes of kind 0, if the build has kinds, one by one); a leaf takes up to
// four tests (sixteen triangles, or four shapes), and a binary node costs one and a half: on the
// 1.1M-triangle bunny, 46.4 bytes a triangle instead of 54.8, with rays as fast or faster
// (bench/README.md).
inline constexpr BvhBuildOptions kWideBvhTriangleBuildOptions{4, 16, 1.5f, 4, 2.0f};

// build_bvh then collapse_to_wide_bvh: deterministic for any number of threads, like build_bvh.
WideBvh build_wide_bvh(std::span<const Bounds3> bounds,
                       const BvhBuildOptions& options = kWideBvhBuildOptions,
                       std::span<const std::uint8_t> kinds = {});

// What a leaf of blocks holds of one primitive, and the id its lane reports.
struct BlockTriangle {
    Point3 v0, v1, v2;
    std::uint32_t id;
};
struct BlockSphere {
    Sphere sphere;
    std::uint32_t id;
};

// What pack_block_leaves makes of a primitive, by its kind (build_bvh's kinds): triangles and
// spheres go into blocks, any other kind stays as it is.
inline constexpr std::uint8_t kBlockTriangle = 1;
inline constexpr std::uint8_t kBlockSphere = 2;

// Turns every leaf whose primitives are all triangles into a leaf of TriangleBlocks, and every
// leaf whose primitives are all spheres into one of SphereBlocks. kinds[i] is primitive i's kind
// (empty: every primitive a triangle); triangle(i) and sphere(i) return primitive i as such, and
// are asked only for primitives of that kind (either may be empty: no such leaves; both are
// called from several threads at once). Within a leaf, lanes run in ascending id, so that the
// lowest lane at equal t is the lowest id. The entries of primitive_indices that such leaves used
// are dropped. Builds whose leaves may mix kinds should separate them (build_bvh's kinds).
void pack_block_leaves(WideBvh& bvh, std::span<const std::uint8_t> kinds,
                       const std::function<BlockTriangle(std::uint32_t)>& triangle,
                       const std::function<BlockSphere(std::uint32_t)>& sphere = {});

}  // namespace glint
