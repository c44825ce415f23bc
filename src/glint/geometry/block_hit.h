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

}  // namespace glint
