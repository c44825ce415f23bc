// What a test of a block of four shapes (triangle_block.h, sphere_block.h) reports: the lane hit
// and where.
#pragma once

namespace glint {

// A hit on lane `lane`: t, and for triangles the barycentric weights of corners 1 and 2. Lane -1
// is no hit. (Not an std::optional: GCC assembles one from narrow stores and reads it back wide,
// a store-forwarding stall in the innermost loop of traversal.)
struct BlockHit {
    float t = 0, u = 0, v = 0;
    int lane = -1;

    explicit operator bool() const { return lane >= 0; }
};

// Accepts every lane (the `accept` of block tests).
inline constexpr auto kEveryLane = [](int) { return true; };

// Of the lanes in `lanes` (bit k for lane k), the nearest hit that accept(lane) takes, the lowest
// lane at equal t. hit_of(k) is lane k's hit, or no hit (lane -1). The one choice both kinds of
// blocks make, on both paths.
template <typename HitOf, typename Accept>
[[gnu::always_inline]] inline BlockHit nearest_lane(unsigned lanes, HitOf&& hit_of,
                                                    Accept&& accept) {
    BlockHit best;
    for (; lanes != 0; lanes &= lanes - 1) {
        const int k = __builtin_ctz(lanes);
        const BlockHit hit = hit_of(k);
        if (hit && (!best || hit.t < best.t) && accept(k)) best = hit;
    }
    return best;
}

// Whether one of the lanes in `lanes` is hit (hit_of, as above) and accepted.
template <typename HitOf, typename Accept>
[[gnu::always_inline]] inline bool any_lane(unsigned lanes, HitOf&& hit_of, Accept&& accept) {
    for (; lanes != 0; lanes &= lanes - 1) {
        const int k = __builtin_ctz(lanes);
        if (hit_of(k) && accept(k)) return true;
    }
    return false;
}

}  // namespace glint
