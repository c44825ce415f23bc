// Traversal of the wide BVH: closest hit (children visited nearest first, subtrees culled once the
// nearest hit is nearer than their boxes) and any hit (stops at the first), calling back per
// primitive as the binary templates of bvh.h do. Allocation-free (a fixed stack), and the same
// primitives are reported in the same order on every SimdPath.
#pragma once

#include <array>
#include <optional>
#include <utility>

#include "glint/geometry/bvh.h"
#include "glint/geometry/bvh4.h"
#include "glint/geometry/bvh4_node_test.h"
#include "glint/geometry/simd_path.h"
#include "glint/math/interval.h"
#include "glint/math/ray.h"

namespace glint {

namespace bvh4 {

// A wide node is at least one binary level below its parent and pushes at most three siblings,
// so a path of kBvhMaxDepth levels never holds more.
inline constexpr int kStackSize = 3 * kBvhMaxDepth;

struct StackEntry {
    std::uint32_t child;  // as in Bvh4Node::child
    std::uint32_t count;  // of a leaf
    float t_near;         // where the ray enters its box
};

// Sorts n (at most 4) entries by t_near, nearest first; stable, so that at equal t_near the lower
// slot stays first and the order does not depend on the kernel.
[[gnu::always_inline]] inline void sort_by_distance(StackEntry* e, int n) {
    for (int i = 1; i < n; ++i) {
        const StackEntry x = e[i];
        int m = i;
        for (; m > 0 && x.t_near < e[m - 1].t_near; --m) e[m] = e[m - 1];
        e[m] = x;
    }
}

template <typename Kernel, typename Visit>
[[gnu::always_inline]] inline std::optional<float> closest_hit(const Bvh4& bvh, const Ray& ray,
                                                               Interval t_range, Visit& visit) {
    const typename Kernel::Ray r{BvhRay(ray)};
    std::array<StackEntry, kStackSize> stack;
    int top = 0;
    std::uint32_t child = 0, count = 0;  // the root, a node
    std::optional<float> nearest;
    for (;;) {
        if ((child & kBvh4Leaf) == 0) {
            const Bvh4Node& node = bvh.nodes[child];
            alignas(16) float t_near[4];
            unsigned mask = Kernel::test(node, r, t_range.min, t_range.max, t_near);
            if (mask != 0) {
                unsigned k = unsigned(__builtin_ctz(mask));
                mask &= mask - 1;
                if (mask == 0) {  // one child: no ordering, no stack
                    child = node.child[k];
                    count = node.count[k];
                    continue;
                }
                unsigned j = unsigned(__builtin_ctz(mask));
                mask &= mask - 1;
                if (mask == 0) {  // two: the nearer now, the other later (the lower slot at a tie)
                    if (t_near[j] < t_near[k]) std::swap(j, k);
                    stack[std::size_t(top++)] = {node.child[j], node.count[j], t_near[j]};
                    child = node.child[k];
                    count = node.count[k];
                    continue;
                }
                // Three or four: sorted, the farthest deepest in the stack, the nearest now.
                StackEntry hit[4] = {{node.child[k], node.count[k], t_near[k]},
                                     {node.child[j], node.count[j], t_near[j]}};
                int n = 2;
                for (; mask != 0; mask &= mask - 1, ++n) {
                    j = unsigned(__builtin_ctz(mask));
                    hit[n] = {node.child[j], node.count[j], t_near[j]};
                }
                sort_by_distance(hit, n);
                for (int i = n - 1; i > 0; --i) stack[std::size_t(top++)] = hit[i];
                child = hit[0].child;
                count = hit[0].count;
                continue;
            }
        } else {
            const std::uint32_t first = child & ~kBvh4Leaf;
            for (std::uint32_t i = 0; i < count; ++i) {
                if (const std::optional<float> t =
                        visit(bvh.primitive_indices[first + i], t_range)) {
                    t_range.max = *t;
                    nearest = t;
                }
            }
        }
        // Entries whose box starts beyond the nearest hit so far hold nothing nearer.
        for (;;) {
            if (top == 0) return nearest;
            const StackEntry& e = stack[std::size_t(--top)];
            if (e.t_near <= t_range.max) {
                child = e.child;
                count = e.count;
                break;
            }
        }
    }
}

template <typename Kernel, typename Visit>
[[gnu::always_inline]] inline bool any_hit(const Bvh4& bvh, const Ray& ray, Interval t_range,
                                           Visit& visit) {
    const typename Kernel::Ray r{BvhRay(ray)};
    std::array<StackEntry, kStackSize> stack;
    int top = 0;
    std::uint32_t child = 0, count = 0;
    for (;;) {
        if ((child & kBvh4Leaf) == 0) {
            const Bvh4Node& node = bvh.nodes[child];
            alignas(16) float t_near[4];
            unsigned mask = Kernel::test(node, r, t_range.min, t_range.max, t_near);
            if (mask != 0) {
                // Any order finds a hit; the lowest slot goes first, the others wait.
                const auto k = unsigned(__builtin_ctz(mask));
                child = node.child[k];
                count = node.count[k];
                for (mask &= mask - 1; mask != 0; mask &= mask - 1) {
                    const auto j = unsigned(__builtin_ctz(mask));
                    stack[std::size_t(top++)] = {node.child[j], node.count[j], t_near[j]};
                }
                continue;
            }
        } else {
            const std::uint32_t first = child & ~kBvh4Leaf;
            for (std::uint32_t i = 0; i < count; ++i) {
                if (visit(bvh.primitive_indices[first + i], t_range)) return true;
            }
        }
        if (top == 0) return false;
        const StackEntry& e = stack[std::size_t(--top)];
        child = e.child;
        count = e.count;
    }
}

#ifdef GLINT_BVH4_HAS_SIMD
// One instantiation per instruction set: the traversal and the callback inline into these, and
// take their target's instructions.
template <typename Visit>
std::optional<float> closest_hit_sse(const Bvh4& bvh, const Ray& ray, Interval t_range,
                                     Visit& visit) {
    return closest_hit<VectorKernel>(bvh, ray, t_range, visit);
}
template <typename Visit>
__attribute__((target("avx2"))) std::optional<float> closest_hit_avx2(const Bvh4& bvh,
                                                                      const Ray& ray,
                                                                      Interval t_range,
                                                                      Visit& visit) {
    return closest_hit<VectorKernel>(bvh, ray, t_range, visit);
}
template <typename Visit>
bool any_hit_sse(const Bvh4& bvh, const Ray& ray, Interval t_range, Visit& visit) {
    return any_hit<VectorKernel>(bvh, ray, t_range, visit);
}
template <typename Visit>
__attribute__((target("avx2"))) bool any_hit_avx2(const Bvh4& bvh, const Ray& ray, Interval t_range,
                                                  Visit& visit) {
    return any_hit<VectorKernel>(bvh, ray, t_range, visit);
}
#endif

}  // namespace bvh4

// Closest hit. visit(primitive_index, Interval) returns the t of that primitive's nearest hit in
// the interval, or nothing; the interval's max then shrinks to it, so later calls only report
// nearer (or equally near) hits. Returns the nearest t, or nothing. Allocates nothing.
template <typename Visit>
std::optional<float> bvh_closest_hit(const Bvh4& bvh, const Ray& ray, Interval t_range,
                                     Visit&& visit) {
    if (bvh.nodes.empty()) return std::nullopt;
#ifdef GLINT_BVH4_HAS_SIMD
    switch (simd_path()) {
        case SimdPath::avx2:
            return bvh4::closest_hit_avx2(bvh, ray, t_range, visit);
        case SimdPath::sse:
            return bvh4::closest_hit_sse(bvh, ray, t_range, visit);
        case SimdPath::scalar:
            break;
    }
#endif
    return bvh4::closest_hit<bvh4::ScalarKernel>(bvh, ray, t_range, visit);
}

// Any hit, for shadow feelers. visit(primitive_index, Interval) returns whether that primitive
// is hit within the interval; traversal stops at the first that is. Allocates nothing.
template <typename Visit>
bool bvh_any_hit(const Bvh4& bvh, const Ray& ray, Interval t_range, Visit&& visit) {
    if (bvh.nodes.empty()) return false;
#ifdef GLINT_BVH4_HAS_SIMD
    switch (simd_path()) {
        case SimdPath::avx2:
            return bvh4::any_hit_avx2(bvh, ray, t_range, visit);
        case SimdPath::sse:
            return bvh4::any_hit_sse(bvh, ray, t_range, visit);
        case SimdPath::scalar:
            break;
    }
#endif
    return bvh4::any_hit<bvh4::ScalarKernel>(bvh, ray, t_range, visit);
}

}  // namespace glint
