// The wide BVH's node test: one ray against the eight child boxes of a WideBvhNode, each exactly as
// slab_hit tests one box (same operations in the same order, t_far by the widened reciprocal, a NaN
// slab bound leaving the interval as it was). Three kernels: a portable scalar one, SSE (two halves
// of four) and AVX2 (all eight at once), in GCC vector extensions. IEEE arithmetic without
// contraction gives all three the same bits.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>

#include "glint/accel/bvh.h"
#include "glint/accel/wide_bvh.h"
#include "glint/math/ray.h"

namespace glint::wide_bvh {

// Rows of WideBvhNode::planes that a ray meets first (near) and last (far) on each axis: the max
// side first where the reciprocal direction is negative (a -0 component included, as in BvhRay).
struct PlaneRows {
    int near[3];
    int far[3];

    explicit PlaneRows(const BvhRay& r) {
        for (int axis = 0; axis < 3; ++axis) {
            near[axis] = r.negative[axis] ? 3 + axis : axis;
            far[axis] = r.negative[axis] ? axis : 3 + axis;
        }
    }
};

struct ScalarKernel {
    static constexpr bool kSimd = false;

    struct Ray {
        float origin[3];
        float inv_direction[3];
        float inv_direction_far[3];
        PlaneRows rows;

        explicit Ray(const BvhRay& r)
            : origin{r.origin.x, r.origin.y, r.origin.z},
              inv_direction{r.inv_direction.x, r.inv_direction.y, r.inv_direction.z},
              inv_direction_far{r.inv_direction_far.x, r.inv_direction_far.y,
                                r.inv_direction_far.z},
              rows(r) {}
    };

    // Bit k set: the ray enters child k's box within [t_min, t_max], at t_near[k].
    [[gnu::always_inline]] static inline unsigned test(const WideBvhNode& node, const Ray& r,
                                                       float t_min, float t_max, float* t_near) {
        unsigned mask = 0;
        for (int k = 0; k < kWideBvhWidth; ++k) {
            float lo = t_min, hi = t_max;
            for (int axis = 0; axis < 3; ++axis) {
                const float n =
                    (node.planes[r.rows.near[axis]][k] - r.origin[axis]) * r.inv_direction[axis];
                const float f =
                    (node.planes[r.rows.far[axis]][k] - r.origin[axis]) * r.inv_direction_far[axis];
                lo = n > lo ? n : lo;
                hi = f < hi ? f : hi;
            }
            t_near[k] = lo;
            mask |= unsigned(lo <= hi) << k;
        }
        return mask;
    }
};

#if defined(__x86_64__) && defined(__GNUC__)
#define GLINT_WIDE_BVH_HAS_SIMD 1

typedef float Float4 __attribute__((vector_size(16)));
typedef int Int4 __attribute__((vector_size(16)));
typedef float Float8 __attribute__((vector_size(32)));
typedef int Int8 __attribute__((vector_size(32)));
// Rows of a node's planes read in place: a row is 32 bytes at a multiple of 32, so loads are
// aligned. may_alias: they read floats. (A memcpy into a local went through the stack.)
typedef float RowOf4 __attribute__((vector_size(16), may_alias));
typedef float RowOf8 __attribute__((vector_size(32), may_alias));

// x in every lane. Not Float4{} + x, which turns -0 into +0.
[[gnu::always_inline]] inline Float4 splat4(float x) { return Float4{x, x, x, x}; }

// Byte offsets of a ray's near and far rows in a node, so that a load needs no index scaling.
struct RowOffsets {
    std::size_t near[3];
    std::size_t far[3];

    explicit RowOffsets(const BvhRay& r) {
        const PlaneRows rows(r);
        for (int axis = 0; axis < 3; ++axis) {
            near[axis] = std::size_t(rows.near[axis]) * sizeof(WideBvhNode::planes[0]);
            far[axis] = std::size_t(rows.far[axis]) * sizeof(WideBvhNode::planes[0]);
        }
    }
};

[[gnu::always_inline]] inline Float4 load4(const WideBvhNode& node, std::size_t offset) {
    return *reinterpret_cast<const RowOf4*>(reinterpret_cast<const char*>(node.planes) + offset);
}

// Four boxes at a time in 128-bit registers: every x86-64 CPU has SSE2.
struct SseKernel {
    static constexpr bool kSimd = true;

    struct Ray {
        Float4 origin[3];
        Float4 inv_direction[3];
        Float4 inv_direction_far[3];
        RowOffsets rows;

        explicit Ray(const BvhRay& r) : rows(r) {
            for (int axis = 0; axis < 3; ++axis) {
                origin[axis] = splat4(r.origin[axis]);
                inv_direction[axis] = splat4(r.inv_direction[axis]);
                inv_direction_far[axis] = splat4(r.inv_direction_far[axis]);
            }
        }
    };

    [[gnu::always_inline]] static inline unsigned test(const WideBvhNode& node, const Ray& r,
                                                       float t_min, float t_max, float* t_near) {
        unsigned mask = 0;
        for (std::size_t half = 0; half < kWideBvhWidth / 4; ++half) {
            const std::size_t at = half * sizeof(Float4);
            Float4 lo = splat4(t_min), hi = splat4(t_max);
            for (int axis = 0; axis < 3; ++axis) {
                const Float4 n =
                    (load4(node, r.rows.near[axis] + at) - r.origin[axis]) * r.inv_direction[axis];
                const Float4 f = (load4(node, r.rows.far[axis] + at) - r.origin[axis]) *
                                 r.inv_direction_far[axis];
                // Element-wise as in slab_hit; these compile to maxps and minps, whose NaN rule
                // (the second operand wins) is the same.
                lo = n > lo ? n : lo;
                hi = f < hi ? f : hi;
            }
            std::memcpy(t_near + 4 * half, &lo, sizeof lo);
            const Int4 inside = lo <= hi;
            mask |= unsigned(__builtin_ia32_movmskps(reinterpret_cast<Float4>(inside)))
                    << (4 * half);
        }
        return mask;
    }
};

// Not always_inline: GCC would refuse it in the generic traversal template before that is inlined
// into its target("avx2") instantiation, where these inline as plain calls between AVX2 functions.
#define GLINT_AVX2 __attribute__((target("avx2")))

// All eight boxes at once in 256-bit registers; only inside target("avx2") functions.
struct Avx2Kernel {
    static constexpr bool kSimd = true;

    GLINT_AVX2 static inline Float8 splat8(float x) { return Float8{x, x, x, x, x, x, x, x}; }
    GLINT_AVX2 static inline Float8 load8(const WideBvhNode& node, std::size_t offset) {
        return *reinterpret_cast<const RowOf8*>(reinterpret_cast<const char*>(node.planes) +
                                                offset);
    }

    struct Ray {
        Float8 origin[3];
        Float8 inv_direction[3];
        Float8 inv_direction_far[3];
        RowOffsets rows;

        GLINT_AVX2 explicit Ray(const BvhRay& r) : rows(r) {
            for (int axis = 0; axis < 3; ++axis) {
                origin[axis] = splat8(r.origin[axis]);
                inv_direction[axis] = splat8(r.inv_direction[axis]);
                inv_direction_far[axis] = splat8(r.inv_direction_far[axis]);
            }
        }
    };

    GLINT_AVX2 static inline unsigned test(const WideBvhNode& node, const Ray& r, float t_min,
                                           float t_max, float* t_near) {
        Float8 lo = splat8(t_min), hi = splat8(t_max);
        for (int axis = 0; axis < 3; ++axis) {
            const Float8 n =
                (load8(node, r.rows.near[axis]) - r.origin[axis]) * r.inv_direction[axis];
            const Float8 f =
                (load8(node, r.rows.far[axis]) - r.origin[axis]) * r.inv_direction_far[axis];
            lo = n > lo ? n : lo;
            hi = f < hi ? f : hi;
        }
        std::memcpy(t_near, &lo, sizeof lo);
        const Int8 inside = lo <= hi;
        return unsigned(__builtin_ia32_movmskps256(reinterpret_cast<Float8>(inside)));
    }
};

#endif

}  // namespace glint::wide_bvh
