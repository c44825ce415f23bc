// A binary bounding volume hierarchy over primitive bounds: a parallel binned-SAH build into a flat
// array of 32-byte nodes, and allocation-free traversal templates (closest hit and any hit) that
// call back per primitive. It is the build stage of the wide BVH (wide_bvh.h), which meshes and the
// scene-level structure trace, and the reference that the wide one is measured against.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "glint/geometry/traversal_counters.h"
#include "glint/math/bounds.h"
#include "glint/math/huge_page_allocator.h"
#include "glint/math/interval.h"
#include "glint/math/ray.h"

namespace glint {

// Deeper trees are never built, so a traversal stack of this many entries cannot overflow.
inline constexpr int kBvhMaxDepth = 64;

struct BvhNode {
    Bounds3 bounds;
    // Interior: index of the second child (the first is the next node). Leaf: index of the first
    // of its `count` entries in Bvh::primitive_indices.
    std::uint32_t offset = 0;
    std::uint16_t count = 0;  // primitives in a leaf; 0 for an interior node
    std::uint8_t axis = 0;    // interior: the axis the children were split along
    std::uint8_t padding = 0;

    bool is_leaf() const { return count > 0; }
};
static_assert(sizeof(BvhNode) == 32, "two nodes to a cache line");

struct BvhBuildOptions {
    // Leaf tests a leaf may take, in [1, 255]: primitives of kind 0, or blocks (block_size
    // primitives of another kind); never more than 255 primitives.
    int max_leaf_size = 4;
    int bins = 16;  // SAH candidates on each axis, in [2, 64]
    // SAH cost of visiting a node relative to one leaf test (pbrt-v4 uses 1/2).
    float traversal_cost = 0.5f;
    // Primitives of a kind other than 0 (see build_bvh) that one leaf test handles at once: SAH
    // counts n of them as ceil(n / block_size) tests (Embree's blocks of four triangles), in
    // [1, 16].
    int block_size = 1;
    // SAH cost of testing one primitive of kind 0 relative to one leaf test of the others.
    float shape_cost = 1;
};

// Nodes that one build task laid out, [begin, end) of Bvh::nodes: a node's children are in its
// own range or are the first nodes of ranges whose parent is its range. Passes from the leaves
// up can take ranges in parallel, each after the ranges below it.
struct BvhNodeRange {
    std::uint32_t begin = 0, end = 0;
    std::int32_t parent = -1;  // index in Bvh::node_ranges; -1 for the root's range
};

struct Bvh {
    LargeVector<BvhNode> nodes;  // nodes[0] is the root; empty for no primitives
    // Leaves refer to ranges of this permutation of the primitives' indices.
    LargeVector<std::uint32_t> primitive_indices;
    // In order of begin, so each after its parent; empty for a tree not made by build_bvh (one
    // range then).
    std::vector<BvhNodeRange> node_ranges;

    Bounds3 bounds() const { return nodes.empty() ? Bounds3{} : nodes[0].bounds; }
};

// Builds over the primitives' bounds (primitive i has bounds[i]). Binned SAH (Wald 2007, "On fast
// Construction of SAH-based Bounding Volume Hierarchies"), 16 bins on each axis of the centroids'
// extent, the cheapest plane of the three taken (as Embree's builder does); where the centroids
// coincide, the boxes' lower corners are binned instead. Where SAH cannot split (all boxes
// alike) or the depth budget runs low, the range is halved by count instead, so every leaf takes
// at most max_leaf_size tests and depth stays below kBvhMaxDepth for up to 2^32 primitives.
// Bounds should be finite; empty or non-finite boxes are kept (they are never hit by the slab
// test) but placed arbitrarily.
// Runs on the calling thread's oneTBB arena (subtrees as tasks, large nodes binned and
// partitioned in fixed blocks); the tree is the same, node for node, for any number of threads.
// With kinds (one per primitive, or empty), no leaf holds primitives of two kinds: a range that
// would become such a leaf is split by kind instead, so that each leaf can be tested its own way.
// Kind 0 is tested one by one, the others (every primitive, without kinds) block_size at a time;
// SAH counts the tests so.
Bvh build_bvh(std::span<const Bounds3> bounds, const BvhBuildOptions& options = {},
              std::span<const std::uint8_t> kinds = {});

// The factor 1 + 2 gamma(3) (pbrt-v4, 6.1.2) by which slab tests widen t_far so that rounding
// never culls a box whose contents the exact test would hit.
inline constexpr float kSlabFarWiden = 1 + 2 * (3 * 5.96046448e-8f) / (1 - 3 * 5.96046448e-8f);

// A ray prepared for slab tests against many boxes: the reciprocal direction is computed once.
struct BvhRay {
    Point3 origin;
    Vector3 inv_direction;
    // inv_direction widened by kSlabFarWiden, for t_far: one multiplication a ray instead of one
    // a box. (d - o) * (r * w) rounds as often as (d - o) * r * w, so it is as conservative.
    Vector3 inv_direction_far;
    // Reciprocal < 0: the ray meets the max side before the min side. Taken from the reciprocal,
    // not the direction, so that a -0 component (1 / -0 = -inf) counts as negative.
    std::array<bool, 3> negative;

    explicit BvhRay(const Ray& ray)
        : origin(ray.origin),
          inv_direction{1 / ray.direction.x, 1 / ray.direction.y, 1 / ray.direction.z},
          inv_direction_far{inv_direction.x * kSlabFarWiden, inv_direction.y * kSlabFarWiden,
                            inv_direction.z * kSlabFarWiden},
          negative{inv_direction.x < 0, inv_direction.y < 0, inv_direction.z < 0} {}
};

// Whether the ray enters the box within [t_min, t_max]. A zero direction component gives an
// infinite reciprocal; a NaN (origin on the slab plane, ray parallel to it) leaves the bound as it
// was, so boundaries count as inside. t_far is widened by kSlabFarWiden (inv_direction_far).
inline bool slab_hit(const Bounds3& b, const BvhRay& r, float t_min, float t_max) {
    for (int axis = 0; axis < 3; ++axis) {
        const float lo = r.negative[axis] ? b.max[axis] : b.min[axis];
        const float hi = r.negative[axis] ? b.min[axis] : b.max[axis];
        const float t_near = (lo - r.origin[axis]) * r.inv_direction[axis];
        const float t_far = (hi - r.origin[axis]) * r.inv_direction_far[axis];
        t_min = t_near > t_min ? t_near : t_min;
        t_max = t_far < t_max ? t_far : t_max;
    }
    return t_min <= t_max;
}

// Closest hit. visit(primitive_index, Interval) returns the t of that primitive's nearest hit in
// the interval, or nothing; the interval's max then shrinks to it, so later calls only report
// nearer hits. Children are visited nearer-first (by the split axis and the direction's sign).
// Returns the nearest t, or nothing. Allocates nothing.
template <typename Visit>
std::optional<float> bvh_closest_hit(const Bvh& bvh, const Ray& ray, Interval t_range,
                                     Visit&& visit) {
    if (bvh.nodes.empty()) return std::nullopt;
    const BvhRay r(ray);
    std::array<std::uint32_t, kBvhMaxDepth> stack;
    int top = 0;
    std::uint32_t node_index = 0;
    std::optional<float> nearest;
    for (;;) {
        const BvhNode& node = bvh.nodes[node_index];
        count_nodes();
        if (slab_hit(node.bounds, r, t_range.min, t_range.max)) {
            if (node.is_leaf()) {
                for (std::uint32_t i = 0; i < node.count; ++i) {
                    const std::uint32_t primitive = bvh.primitive_indices[node.offset + i];
                    if (const std::optional<float> t = visit(primitive, t_range)) {
                        t_range.max = *t;
                        nearest = t;
                    }
                }
            } else if (r.negative[node.axis]) {
                stack[top++] = node_index + 1;  // the second child lies nearer
                node_index = node.offset;
                continue;
            } else {
                stack[top++] = node.offset;
                node_index = node_index + 1;
                continue;
            }
        }
        if (top == 0) return nearest;
        node_index = stack[--top];
    }
}

// Any hit, for shadow feelers. visit(primitive_index, Interval) returns whether that primitive
// is hit within the interval; traversal stops at the first that is. Allocates nothing.
template <typename Visit>
bool bvh_any_hit(const Bvh& bvh, const Ray& ray, Interval t_range, Visit&& visit) {
    if (bvh.nodes.empty()) return false;
    const BvhRay r(ray);
    std::array<std::uint32_t, kBvhMaxDepth> stack;
    int top = 0;
    std::uint32_t node_index = 0;
    for (;;) {
        const BvhNode& node = bvh.nodes[node_index];
        count_nodes();
        if (slab_hit(node.bounds, r, t_range.min, t_range.max)) {
            if (node.is_leaf()) {
                for (std::uint32_t i = 0; i < node.count; ++i) {
                    if (visit(bvh.primitive_indices[node.offset + i], t_range)) return true;
                }
            } else {
                const bool second_first = r.negative[node.axis];
                stack[top++] = second_first ? node_index + 1 : node.offset;
                node_index = second_first ? node.offset : node_index + 1;
                continue;
            }
        }
        if (top == 0) return false;
        node_index = stack[--top];
    }
}

}  // namespace glint
