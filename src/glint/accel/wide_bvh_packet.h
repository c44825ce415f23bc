// Up to eight rays traced through the wide BVH together, one ray to an AVX2 lane (Wald, Slusallek,
// Benthin and Wagner 2001, "Interactive Rendering with Coherent Ray Tracing"; Embree's
// rtcIntersect8): a node is fetched, and its children ordered and pushed, once for the rays that
// enter it, and each child's box is tested against all of them at once. A subtree that only a few
// rays still enter is finished ray by ray (wide_bvh_traversal.h), as rays of a packet diverge.
// Each ray meets every box through slab_hit's operations and every leaf through the single-ray
// leaf test, so its hit is bit for bit the one it gets alone, wherever ties are broken by the
// leaf test (as MeshBvh's are, by triangle index) rather than by the order of the leaves.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <span>

#include "glint/accel/wide_bvh_traversal.h"

namespace glint {

namespace wide_bvh {

#ifdef GLINT_WIDE_BVH_HAS_SIMD

// A subtree that at most this many of the packet's rays enter is traced ray by ray.
inline constexpr int kPacketSingleRays = 2;

// The packet's rays, lane by lane (lanes past the last ray repeat it and are never active).
struct Packet8 {
    Float8 origin[3];
    Float8 inv_direction[3];
    Float8 inv_direction_far[3];
    Int8 negative[3];  // all bits set where the ray meets the max side first

    GLINT_AVX2 explicit Packet8(std::span<const Ray> rays) {
        for (int lane = 0; lane < kRayPacketSize; ++lane) {
            const BvhRay r(rays[std::min(std::size_t(lane), rays.size() - 1)]);
            for (int axis = 0; axis < 3; ++axis) {
                origin[axis][lane] = r.origin[axis];
                inv_direction[axis][lane] = r.inv_direction[axis];
                inv_direction_far[axis][lane] = r.inv_direction_far[axis];
                negative[axis][lane] = r.negative[axis] ? -1 : 0;
            }
        }
    }
};

// The lanes whose ray enters slot k's box within its [t_min, t_max], entering at t_near: each
// lane as slab_hit, its near side chosen by its own direction.
GLINT_AVX2 inline Int8 test_slot(const WideBvhNode& node, int k, const Packet8& p, Float8 t_min,
                                 Float8 t_max, Float8& t_near) {
    Float8 lo = t_min, hi = t_max;
    for (int axis = 0; axis < 3; ++axis) {
        const Float8 min_side = Avx2Kernel::splat8(node.planes[axis][k]);
        const Float8 max_side = Avx2Kernel::splat8(node.planes[3 + axis][k]);
        const Float8 near_side = p.negative[axis] ? max_side : min_side;
        const Float8 far_side = p.negative[axis] ? min_side : max_side;
        const Float8 n = (near_side - p.origin[axis]) * p.inv_direction[axis];
        const Float8 f = (far_side - p.origin[axis]) * p.inv_direction_far[axis];
        lo = n > lo ? n : lo;
        hi = f < hi ? f : hi;
    }
    t_near = lo;
    return lo <= hi;
}

// Lanes as a bit mask, and back.
GLINT_AVX2 inline unsigned lane_bits(Int8 lanes) {
    return unsigned(__builtin_ia32_movmskps256(reinterpret_cast<Float8>(lanes)));
}
GLINT_AVX2 inline Int8 lane_vector(unsigned bits) {
    const Int8 bit{1, 2, 4, 8, 16, 32, 64, 128};
    const int b = int(bits);
    return (bit & Int8{b, b, b, b, b, b, b, b}) != 0;
}

// The least of the lanes of x.
GLINT_AVX2 inline float horizontal_min(Float8 x) {
    const Float8 a = __builtin_shufflevector(x, x, 4, 5, 6, 7, 0, 1, 2, 3);
    x = a < x ? a : x;
    const Float8 b = __builtin_shufflevector(x, x, 2, 3, 0, 1, 6, 7, 4, 5);
    x = b < x ? b : x;
    const Float8 c = __builtin_shufflevector(x, x, 1, 0, 3, 2, 5, 4, 7, 6);
    x = c < x ? c : x;
    return x[0];
}

// A subtree and the lanes that enter it; t_near is the nearest lane's entry.
struct PacketEntry {
    std::uint32_t child;
    std::uint32_t count;
    unsigned lanes;
    float t_near;
};

// The rays' ranges as vectors, for the node tests (lanes past the last ray repeat it).
struct PacketRanges {
    Float8 t_min;
    Float8 t_max;

    GLINT_AVX2 void load(const Interval* ranges, std::size_t rays) {
        for (std::size_t lane = 0; lane < std::size_t(kRayPacketSize); ++lane) {
            const Interval& range = ranges[std::min(lane, rays - 1)];
            t_min[lane] = range.min;
            t_max[lane] = range.max;
        }
    }
};

// The node's children that some active lane enters, in slot order, into hit; returns how many.
GLINT_AVX2 inline int enter_children(const WideBvhNode& node, const Packet8& p, unsigned lanes,
                                     const PacketRanges& r, PacketEntry* hit) {
    const Int8 active = lane_vector(lanes);
    int n = 0;
    for (int k = 0; k < kWideBvhWidth; ++k) {
        if (node.is_leaf(k) && node.count[k] == 0) continue;  // an unused slot
        Float8 t_near;
        const Int8 entering = test_slot(node, k, p, r.t_min, r.t_max, t_near) & active;
        const unsigned bits = lane_bits(entering);
        if (bits == 0) continue;
        const float nearest = horizontal_min(entering ? t_near : Avx2Kernel::splat8(kInfinity));
        hit[n++] = {node.child[k], node.count[k], bits, nearest};
    }
    return n;
}

// The lanes of `lanes` whose range still reaches t.
GLINT_AVX2 inline unsigned reaching(unsigned lanes, float t, const PacketRanges& r) {
    return lane_bits(Avx2Kernel::splat8(t) <= r.t_max) & lanes;
}

// Replaces `current`, a node, by its child that its lanes enter (nearest first, or the lowest slot)
// and pushes the others to come after it; false when no lane enters a child.
template <bool kNearestFirst>
GLINT_AVX2 inline bool descend(const WideBvh& bvh, const Packet8& p, const PacketRanges& r,
                               PacketEntry& current, PacketEntry* stack, int& top) {
    const WideBvhNode& node = bvh.nodes[current.child];
    count_nodes();
    PacketEntry hit[kWideBvhWidth];
    const int n = enter_children(node, p, current.lanes, r, hit);
    if (n == 0) return false;
    if constexpr (kNearestFirst) sort_by_distance(hit, n);
    for (int i = n - 1; i > 0; --i) stack[top++] = hit[i];
    current = hit[0];
    return true;
}

// Closest hits: visit(kernel, leaf, count, lane, Interval& range) tests one lane's ray against a
// leaf and brings ranges[lane].max to a nearer hit. Children are taken nearest first (by their
// nearest lane) and dropped when no lane's range reaches them any more.
template <typename Visit>
GLINT_AVX2 void closest_hit_packet(const WideBvh& bvh, std::span<const Ray> rays, Interval* ranges,
                                   Visit& visit) {
    const Packet8 p(rays);
    PacketRanges r;
    r.load(ranges, rays.size());
    std::array<PacketEntry, kStackSize> stack;
    int top = 0;
    PacketEntry current{0, 0, (1u << rays.size()) - 1, -kInfinity};
    for (;;) {
        if (std::popcount(current.lanes) <= kPacketSingleRays) {
            for (unsigned m = current.lanes; m != 0; m &= m - 1) {
                const int lane = __builtin_ctz(m);
                auto one = [&](auto kernel, std::uint32_t leaf, std::uint32_t count,
                               Interval& range) GLINT_INLINE_LEAF {
                    visit(kernel, leaf, count, lane, range);
                    ranges[lane].max = range.max;
                };
                closest_hit<Avx2Kernel>(bvh, rays[std::size_t(lane)], ranges[lane], one,
                                        current.child, current.count);
            }
            r.load(ranges, rays.size());
        } else if ((current.child & kWideLeaf) == 0) {
            if (descend<true>(bvh, p, r, current, stack.data(), top)) continue;
        } else {
            for (unsigned m = current.lanes; m != 0; m &= m - 1) {
                const int lane = __builtin_ctz(m);
                visit(Avx2Kernel{}, current.child, current.count, lane, ranges[lane]);
            }
            r.load(ranges, rays.size());
        }
        for (;;) {
            if (top == 0) return;
            const PacketEntry& e = stack[std::size_t(--top)];
            const unsigned lanes = reaching(e.lanes, e.t_near, r);
            if (lanes != 0) {
                current = {e.child, e.count, lanes, e.t_near};
                break;
            }
        }
    }
}

// Any hit: visit(kernel, leaf, count, lane, Interval range) returns whether the leaf blocks that
// lane's ray. Returns the lanes blocked; a lane stops at its first hit, the packet when all have.
template <typename Visit>
GLINT_AVX2 unsigned any_hit_packet(const WideBvh& bvh, std::span<const Ray> rays,
                                   const Interval* ranges, Visit& visit) {
    const Packet8 p(rays);
    PacketRanges r;
    r.load(ranges, rays.size());
    std::array<PacketEntry, kStackSize> stack;
    int top = 0;
    const unsigned all = (1u << rays.size()) - 1;
    unsigned blocked = 0;
    PacketEntry current{0, 0, all, -kInfinity};
    for (;;) {
        current.lanes &= ~blocked;
        if (std::popcount(current.lanes) <= kPacketSingleRays) {
            for (unsigned m = current.lanes; m != 0; m &= m - 1) {
                const int lane = __builtin_ctz(m);
                auto one =
                    [&](auto kernel, std::uint32_t leaf, std::uint32_t count, Interval range)
                        GLINT_INLINE_LEAF { return visit(kernel, leaf, count, lane, range); };
                if (any_hit<Avx2Kernel>(bvh, rays[std::size_t(lane)], ranges[lane], one,
                                        current.child, current.count))
                    blocked |= 1u << lane;
            }
        } else if ((current.child & kWideLeaf) == 0) {
            // Slot order, as a single ray's any hit takes them.
            if (descend<false>(bvh, p, r, current, stack.data(), top)) continue;
        } else {
            for (unsigned m = current.lanes; m != 0; m &= m - 1) {
                const int lane = __builtin_ctz(m);
                if (visit(Avx2Kernel{}, current.child, current.count, lane, ranges[lane]))
                    blocked |= 1u << lane;
            }
        }
        if (blocked == all) return blocked;
        for (;;) {
            if (top == 0) return blocked;
            current = stack[std::size_t(--top)];
            if ((current.lanes & ~blocked) != 0) break;
        }
    }
}

#endif

}  // namespace wide_bvh

// Closest hits of up to kRayPacketSize rays traced together: visit(kernel, leaf, count, lane,
// Interval& range) tests ray `lane` against a leaf as bvh_closest_leaf's visit does, bringing
// range.max (ranges[lane].max) to a nearer hit. Packets on the AVX2 path; elsewhere the rays are
// traced one by one. Allocates nothing.
template <typename VisitLeaf>
void bvh_closest_leaf_packet(const WideBvh& bvh, std::span<const Ray> rays, Interval* ranges,
                             VisitLeaf&& visit) {
    if (bvh.nodes.empty() || rays.empty()) return;
#ifdef GLINT_WIDE_BVH_HAS_SIMD
    if (simd_path() == SimdPath::avx2) {
        wide_bvh::closest_hit_packet(bvh, rays, ranges, visit);
        return;
    }
#endif
    for (std::size_t lane = 0; lane < rays.size(); ++lane) {
        bvh_closest_leaf(bvh, rays[lane], ranges[lane],
                         [&](auto kernel, std::uint32_t leaf, std::uint32_t count, Interval& range)
                             GLINT_INLINE_LEAF {
                                 visit(kernel, leaf, count, int(lane), range);
                                 ranges[lane].max = range.max;
                             });
    }
}

// Any hits of up to kRayPacketSize shadow feelers traced together: visit(kernel, leaf, count,
// lane, Interval range) returns whether the leaf blocks ray `lane`. Returns the blocked lanes.
template <typename VisitLeaf>
unsigned bvh_any_leaf_packet(const WideBvh& bvh, std::span<const Ray> rays, const Interval* ranges,
                             VisitLeaf&& visit) {
    if (bvh.nodes.empty() || rays.empty()) return 0;
#ifdef GLINT_WIDE_BVH_HAS_SIMD
    if (simd_path() == SimdPath::avx2) return wide_bvh::any_hit_packet(bvh, rays, ranges, visit);
#endif
    unsigned blocked = 0;
    for (std::size_t lane = 0; lane < rays.size(); ++lane) {
        if (bvh_any_leaf(
                bvh, rays[lane], ranges[lane],
                [&](auto kernel, std::uint32_t leaf, std::uint32_t count, Interval range)
                    GLINT_INLINE_LEAF { return visit(kernel, leaf, count, int(lane), range); }))
            blocked |= 1u << lane;
    }
    return blocked;
}

}  // namespace glint
