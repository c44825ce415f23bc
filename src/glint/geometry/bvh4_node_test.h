// The wide BVH's node test: one ray against the four child boxes of a Bvh4Node, each exactly as
// slab_hit tests one box (same operations in the same order, t_far widened by kSlabFarWiden, a NaN
// slab bound leaving the interval as it was). Two kernels: a portable scalar one, and one in GCC
// vector extensions that compiles to SSE, or to AVX2 inside a target("avx2") function. IEEE
// arithmetic without contraction gives both the same bits.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>

#include "glint/geometry/bvh.h"
#include "glint/geometry/bvh4.h"
#include "glint/math/ray.h"

namespace glint::bvh4 {

// Rows of Bvh4Node::planes that a ray meets first (near) and last (far) on each axis: the max side
// first where the reciprocal direction is negative (a -0 component included, as in BvhRay).
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
    struct Ray {
        float origin[3];
        float inv_direction[3];
        PlaneRows rows;

        explicit Ray(const BvhRay& r)
            : origin{r.origin.x, r.origin.y, r.origin.z},
              inv_direction{r.inv_direction.x, r.inv_direction.y, r.inv_direction.z},
              rows(r) {}
    };

    // Bit k set: the ray enters child k's box within [t_min, t_max], at t_near[k].
    [[gnu::always_inline]] static inline unsigned test(const Bvh4Node& node, const Ray& r,
                                                       float t_min, float t_max, float* t_near) {
        unsigned mask = 0;
        for (int k = 0; k < 4; ++k) {
            float lo = t_min, hi = t_max;
            for (int axis = 0; axis < 3; ++axis) {
                const float n =
                    (node.planes[r.rows.near[axis]][k] - r.origin[axis]) * r.inv_direction[axis];
                const float f = (node.planes[r.rows.far[axis]][k] - r.origin[axis]) *
                                r.inv_direction[axis] * kSlabFarWiden;
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
#define GLINT_BVH4_HAS_SIMD 1

// Four floats, and the comparison result of two.
typedef float Float4 __attribute__((vector_size(16)));
typedef int Int4 __attribute__((vector_size(16)));

// x in every lane. Not Float4{} + x, which turns -0 into +0.
[[gnu::always_inline]] inline Float4 splat(float x) { return Float4{x, x, x, x}; }

struct VectorKernel {
    struct Ray {
        Float4 origin[3];
        Float4 inv_direction[3];
        // Byte offsets of the near and far rows in a node, so that a load needs no index scaling.
        std::size_t near[3];
        std::size_t far[3];

        explicit Ray(const BvhRay& r) {
            const PlaneRows rows(r);
            for (int axis = 0; axis < 3; ++axis) {
                origin[axis] = splat(r.origin[axis]);
                inv_direction[axis] = splat(r.inv_direction[axis]);
                near[axis] = std::size_t(rows.near[axis]) * sizeof(Float4);
                far[axis] = std::size_t(rows.far[axis]) * sizeof(Float4);
            }
        }
    };

    [[gnu::always_inline]] static inline Float4 load(const Bvh4Node& node, std::size_t offset) {
        Float4 v;
        std::memcpy(&v, reinterpret_cast<const char*>(node.planes) + offset, sizeof v);
        return v;
    }

    [[gnu::always_inline]] static inline unsigned test(const Bvh4Node& node, const Ray& r,
                                                       float t_min, float t_max, float* t_near) {
        const Float4 widen = splat(kSlabFarWiden);
        Float4 lo = splat(t_min), hi = splat(t_max);
        for (int axis = 0; axis < 3; ++axis) {
            const Float4 n = (load(node, r.near[axis]) - r.origin[axis]) * r.inv_direction[axis];
            const Float4 f =
                (load(node, r.far[axis]) - r.origin[axis]) * r.inv_direction[axis] * widen;
            // Element-wise as in slab_hit; these compile to maxps and minps, whose NaN rule
            // (the second operand wins) is the same.
            lo = n > lo ? n : lo;
            hi = f < hi ? f : hi;
        }
        std::memcpy(t_near, &lo, sizeof lo);
        const Int4 inside = lo <= hi;
        return unsigned(__builtin_ia32_movmskps(reinterpret_cast<Float4>(inside)));
    }
};

#endif

}  // namespace glint::bvh4
