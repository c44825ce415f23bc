// Traversal of the wide BVH: closest hit (children visited nearest first, subtrees culled once the
// nearest hit is nearer than their boxes) and any hit (children in slot order, stops at the first
// hit), calling back per leaf (or per primitive, as the binary templates of bvh.h do).
// Allocation-free (a fixed stack), and the same leaves are visited in the same order on every
// SimdPath.
#pragma once

#include <array>
#include <optional>
#include <span>
#include <utility>

#include "glint/accel/bvh.h"
#include "glint/accel/wide_bvh.h"
#include "glint/accel/wide_bvh_node_test.h"
#include "glint/geometry/simd_path.h"
#include "glint/math/interval.h"
#include "glint/math/ray.h"

// For leaf callbacks: inlined into each traversal instantiation, so that they take its
// instruction set (VEX-encoded in the AVX2 one) and keep the ray in registers across leaves.
#define GLINT_INLINE_LEAF __attribute__((always_inline))

namespace glint {

namespace wide_bvh {

// A wide node is at least one binary level below its parent and pushes at most all but one of its
// children, so a path of kBvhMaxDepth levels never holds more.
inline constexpr int kStackSize = (kWideBvhWidth - 1) * kBvhMaxDepth;

struct StackEntry {
    std::uint32_t child;  // as in WideBvhNode::child
    std::uint32_t count;  // of a leaf
    float t_near;         // where the ray enters its box
};

// Sorts n (at most kWideBvhWidth) entries by t_near, nearest first; stable, so that at equal t_near
// the lower slot stays first and the order does not depend on the kernel. Entries of a single ray
// or of a packet (wide_bvh_packet.h).
template <typename Entry>
[[gnu::always_inline]] inline void sort_by_distance(Entry* e, int n) {
    for (int i = 1; i < n; ++i) {
        const Entry x = e[i];
        int m = i;
        for (; m > 0 && x.t_near < e[m - 1].t_near; --m) e[m] = e[m - 1];
        e[m] = x;
    }
}

// The node's children in `mask` (entered at t_near): goes on to the nearest one (child, count)
// and pushes the others, the farthest deepest, for closest hit to cull by the nearest hit found.
[[gnu::always_inline]] inline void descend(const WideBvhNode& node, unsigned mask,
                                           const float* t_near, StackEntry* stack, int& top,
                                           std::uint32_t& child, std::uint32_t& count) {
    unsigned k = unsigned(__builtin_ctz(mask));
    mask &= mask - 1;
    if (mask == 0) {  // one child: no ordering, no stack
        child = node.child[k];
        count = node.count[k];
        return;
    }
    unsigned j = unsigned(__builtin_ctz(mask));
    mask &= mask - 1;
    if (mask == 0) {  // two: the nearer now, the other later (the lower slot at a tie)
        if (t_near[j] < t_near[k]) std::swap(j, k);
        stack[top++] = {node.child[j], node.count[j], t_near[j]};
        child = node.child[k];
        count = node.count[k];
        return;
    }
    StackEntry hit[kWideBvhWidth];  // not zero-filled: only n entries are used
    hit[0] = {node.child[k], node.count[k], t_near[k]};
    hit[1] = {node.child[j], node.count[j], t_near[j]};
    int n = 2;
    for (; mask != 0; mask &= mask - 1, ++n) {
        j = unsigned(__builtin_ctz(mask));
        hit[n] = {node.child[j], node.count[j], t_near[j]};
    }
    sort_by_distance(hit, n);
    for (int i = n - 1; i > 0; --i) stack[top++] = hit[i];
    child = hit[0].child;
    count = hit[0].count;
}

// From the subtree `child` (count as in StackEntry; the root, a node, by default).
template <typename Kernel, typename Visit>
[[gnu::always_inline]] inline void closest_hit(const WideBvh& bvh, const Ray& ray, Interval t_range,
                                               Visit& visit, std::uint32_t child = 0,
                                               std::uint32_t count = 0) {
    const typename Kernel::Ray r{BvhRay(ray)};
    std::array<StackEntry, kStackSize> stack;
    int top = 0;
    for (;;) {
        if ((child & kWideLeaf) == 0) {
            const WideBvhNode& node = bvh.nodes[child];
            alignas(32) float t_near[kWideBvhWidth];
            count_nodes();
            const unsigned mask = Kernel::test(node, r, t_range.min, t_range.max, t_near);
            if (mask != 0) {
                descend(node, mask, t_near, stack.data(), top, child, count);
                continue;
            }
        } else {
            visit(Kernel{}, child, count, t_range);  // may bring t_range.max nearer
        }
        // Entries whose box starts beyond the nearest hit so far hold nothing nearer.
        for (;;) {
            if (top == 0) return;
            const StackEntry& e = stack[std::size_t(--top)];
            if (e.t_near <= t_range.max) {
                child = e.child;
                count = e.count;
                break;
            }
        }
    }
}

// The node's children in `mask`: goes on to the one in the lowest slot and pushes the others, for
// any hit. Not nearest first: a feeler leaving a surface enters first the boxes around its origin,
// which seldom hold what blocks it (measured on the SPD scenes: shadow rays up to 1.48x as fast,
// rings-s20 with 17% fewer shape tests; none more than 5% slower; bench/README.md).
[[gnu::always_inline]] inline void descend_in_slot_order(const WideBvhNode& node, unsigned mask,
                                                         const float* t_near, StackEntry* stack,
                                                         int& top, std::uint32_t& child,
                                                         std::uint32_t& count) {
    const unsigned first = unsigned(__builtin_ctz(mask));
    child = node.child[first];
    count = node.count[first];
    // The highest slot deepest, so that the others come off the stack in slot order.
    for (unsigned rest = mask & (mask - 1); rest != 0;) {
        const unsigned k = 31u - unsigned(__builtin_clz(rest));
        rest &= ~(1u << k);
        stack[top++] = {node.child[k], node.count[k], t_near[k]};
    }
}

template <typename Kernel, typename Visit>
[[gnu::always_inline]] inline bool any_hit(const WideBvh& bvh, const Ray& ray, Interval t_range,
                                           Visit& visit, std::uint32_t child = 0,
                                           std::uint32_t count = 0) {
    const typename Kernel::Ray r{BvhRay(ray)};
    std::array<StackEntry, kStackSize> stack;
    int top = 0;
    for (;;) {
        if ((child & kWideLeaf) == 0) {
            const WideBvhNode& node = bvh.nodes[child];
            alignas(32) float t_near[kWideBvhWidth];
            count_nodes();
            const unsigned mask = Kernel::test(node, r, t_range.min, t_range.max, t_near);
            if (mask != 0) {
                descend_in_slot_order(node, mask, t_near, stack.data(), top, child, count);
                continue;
            }
        } else if (visit(Kernel{}, child, count, t_range)) {
            return true;
        }
        if (top == 0) return false;
        const StackEntry& e = stack[std::size_t(--top)];
        child = e.child;
        count = e.count;
    }
}

// Either query with one kernel: closest hit (kAny false) or any hit.
template <typename Kernel, bool kAny, typename Visit>
[[gnu::always_inline]] inline bool query(const WideBvh& bvh, const Ray& ray, Interval t_range,
                                         Visit& visit) {
    if constexpr (kAny) {
        return any_hit<Kernel>(bvh, ray, t_range, visit);
    } else {
        closest_hit<Kernel>(bvh, ray, t_range, visit);
        return false;
    }
}

// One instantiation per instruction set: the traversal and the callback inline into these, and
// take their target's instructions. Out of line, so that query_on_path, which every ray passes
// through, stays a switch without the traversals' stacks in its frame.
template <bool kAny, typename Visit>
[[gnu::noinline]] bool query_scalar(const WideBvh& bvh, const Ray& ray, Interval t_range,
                                    Visit& visit) {
    return query<ScalarKernel, kAny>(bvh, ray, t_range, visit);
}
#ifdef GLINT_WIDE_BVH_HAS_SIMD
template <bool kAny, typename Visit>
[[gnu::noinline]] bool query_sse(const WideBvh& bvh, const Ray& ray, Interval t_range,
                                 Visit& visit) {
    return query<SseKernel, kAny>(bvh, ray, t_range, visit);
}
template <bool kAny, typename Visit>
__attribute__((target("avx2"))) bool query_avx2(const WideBvh& bvh, const Ray& ray,
                                                Interval t_range, Visit& visit) {
    return query<Avx2Kernel, kAny>(bvh, ray, t_range, visit);
}
#endif

// The query on the SIMD path in use.
template <bool kAny, typename Visit>
bool query_on_path(const WideBvh& bvh, const Ray& ray, Interval t_range, Visit& visit) {
    if (bvh.nodes.empty()) return false;
#ifdef GLINT_WIDE_BVH_HAS_SIMD
    switch (simd_path()) {
        case SimdPath::avx2:
            return query_avx2<kAny>(bvh, ray, t_range, visit);
        case SimdPath::sse:
            return query_sse<kAny>(bvh, ray, t_range, visit);
        case SimdPath::scalar:
            break;
    }
#endif
    return query_scalar<kAny>(bvh, ray, t_range, visit);
}

}  // namespace wide_bvh

// Closest hit, leaf by leaf. visit(kernel, leaf, count, Interval& range) tests the leaf `leaf` (a
// child reference with kWideLeaf set; `count` its entries) and, when it finds a nearer hit in
// range, brings range.max to it (so later calls only report nearer, or equally near, hits).
// `kernel` is the node test's (wide_bvh::ScalarKernel, SseKernel or Avx2Kernel): the path this
// traversal runs on, for leaf tests that have SIMD forms too (its kSimd). The caller keeps what
// it found. Allocates nothing.
template <typename VisitLeaf>
void bvh_closest_leaf(const WideBvh& bvh, const Ray& ray, Interval t_range, VisitLeaf&& visit) {
    wide_bvh::query_on_path<false>(bvh, ray, t_range, visit);
}

// Any hit, leaf by leaf, for shadow feelers: visit(kernel, leaf, count, Interval) returns whether
// the leaf holds a hit within the interval; traversal stops at the first that does.
template <typename VisitLeaf>
bool bvh_any_leaf(const WideBvh& bvh, const Ray& ray, Interval t_range, VisitLeaf&& visit) {
    return wide_bvh::query_on_path<true>(bvh, ray, t_range, visit);
}

// What a leaf holds (kWidePrimitiveLeaf, kWideTriangleLeaf or kWideSphereLeaf).
inline std::uint32_t leaf_kind(std::uint32_t leaf) { return leaf & kWideLeafKind; }

// The primitives of a leaf of primitive_indices.
inline std::span<const std::uint32_t> leaf_primitives(const WideBvh& bvh, std::uint32_t leaf,
                                                      std::uint32_t count) {
    return {bvh.primitive_indices.data() + (leaf & kWideLeafIndex), count};
}

// The blocks of a leaf of triangles.
inline std::span<const TriangleBlock> leaf_blocks(const WideBvh& bvh, std::uint32_t leaf,
                                                  std::uint32_t count) {
    return {bvh.blocks.data() + (leaf & kWideLeafIndex), count};
}

// The blocks of a leaf of spheres.
inline std::span<const SphereBlock> leaf_sphere_blocks(const WideBvh& bvh, std::uint32_t leaf,
                                                       std::uint32_t count) {
    return {bvh.sphere_blocks.data() + (leaf & kWideLeafIndex), count};
}

// Closest hit over a tree whose leaves are all of primitives. visit(primitive_index, Interval)
// returns the t of that primitive's nearest hit in the interval, or nothing; the interval's max
// then shrinks to it, so later calls only report nearer (or equally near) hits. Returns the
// nearest t, or nothing. Allocates nothing.
template <typename Visit>
std::optional<float> bvh_closest_hit(const WideBvh& bvh, const Ray& ray, Interval t_range,
                                     Visit&& visit) {
    std::optional<float> nearest;
    bvh_closest_leaf(bvh, ray, t_range,
                     [&](auto, std::uint32_t leaf, std::uint32_t count, Interval& range) {
                         for (const std::uint32_t i : leaf_primitives(bvh, leaf, count)) {
                             if (const std::optional<float> t = visit(i, range)) {
                                 range.max = *t;
                                 nearest = t;
                             }
                         }
                     });
    return nearest;
}

// Any hit over a tree whose leaves are all of primitives, for shadow feelers.
// visit(primitive_index, Interval) returns whether that primitive is hit within the interval;
// traversal stops at the first that is. Allocates nothing.
template <typename Visit>
bool bvh_any_hit(const WideBvh& bvh, const Ray& ray, Interval t_range, Visit&& visit) {
    return bvh_any_leaf(bvh, ray, t_range,
                        [&](auto, std::uint32_t leaf, std::uint32_t count, Interval range) {
                            for (const std::uint32_t i : leaf_primitives(bvh, leaf, count))
                                if (visit(i, range)) return true;
                            return false;
                        });
}

}  // namespace glint
