// What a test of a block of four shapes (triangle_block.h, sphere_block.h) reports: the lane hit
// and where.
#pragma once

namespace glint {

// A hit on lane `lane`: t, and for triangles the barycentric weights of corners 1 and 2.
struct BlockHit {
    float t, u, v;
    int lane;
};

// Accepts every lane (the `accept` of block tests).
inline constexpr auto kEveryLane = [](int) { return true; };

}  // namespace glint
