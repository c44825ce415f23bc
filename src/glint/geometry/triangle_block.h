// Four triangles side by side, so that one SIMD pass runs the watertight test
// (watertight_triangle.h) on all of them: the leaves of wide BVHs over triangles (Embree's
// Triangle4). Every lane's answer is exactly intersect_watertight's for that triangle.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>

#include "glint/geometry/block_hit.h"
#include "glint/geometry/traversal_counters.h"
#include "glint/geometry/watertight_triangle.h"
#include "glint/math/interval.h"
#include "glint/math/ray.h"

namespace glint {

// The id of an unused lane.
inline constexpr std::uint32_t kNoTriangle = 0xffffffffu;

struct alignas(16) TriangleBlock {
    // v[corner][axis][lane]: one row of four coordinates, so that a SIMD load takes a row.
    float v[3][3][4];
    // What the owner calls each lane's triangle (a mesh's triangle index, a reference). An unused
    // lane has kNoTriangle and NaN corners, which no ray hits.
    std::uint32_t id[4];

    Point3 corner(int lane, int c) const { return {v[c][0][lane], v[c][1][lane], v[c][2][lane]}; }
};
static_assert(sizeof(TriangleBlock) == 160, "five 32-byte rows, two and a half cache lines");

// A block of four unused lanes.
TriangleBlock empty_triangle_block();

// Puts the triangle (v0, v1, v2) in `lane`. A triangle that intersect_watertight never hits (its
// edges' float cross product is zero) gets an unused lane instead, with `id` all the same: a lane
// tests only what can be hit.
void set_block_lane(TriangleBlock& block, int lane, Point3 v0, Point3 v1, Point3 v2,
                    std::uint32_t id);

// A ray prepared for block tests: the shear once a ray, and its rows in SIMD registers.
struct BlockRay {
    Ray ray;
    RayShear shear;

    explicit BlockRay(const Ray& r) : ray(r), shear(r.direction) {}
};

#if defined(__x86_64__) && defined(__GNUC__)
#define GLINT_TRIANGLE_BLOCK_HAS_SIMD 1

namespace block_simd {

// GCC vector extensions: SSE, or AVX2 inside target("avx2") functions. No fused multiply-adds
// (glint is not built with -mfma, and target("avx2") does not enable them), so each operation
// rounds as the scalar test's does.
typedef float Float4 __attribute__((vector_size(16)));
typedef int Int4 __attribute__((vector_size(16)));

[[gnu::always_inline]] inline Float4 splat(float x) { return Float4{x, x, x, x}; }

[[gnu::always_inline]] inline unsigned mask_of(Int4 m) {
    return unsigned(__builtin_ia32_movmskps(reinterpret_cast<Float4>(m)));
}

[[gnu::always_inline]] inline Float4 abs(Float4 x) {
    const int m = 0x7fffffff;
    return reinterpret_cast<Float4>(reinterpret_cast<Int4>(x) & Int4{m, m, m, m});
}

// The ray in the shear's frame, in every lane; rows are picked by byte offsets into a corner.
struct Ray4 {
    std::size_t kx, ky, kz;
    Float4 ox, oy, oz;  // origin components along kx, ky, kz
    Float4 sx, sy, sz;

    explicit Ray4(const BlockRay& r) {
        const float o[3] = {r.ray.origin.x, r.ray.origin.y, r.ray.origin.z};
        kx = std::size_t(r.shear.kx) * sizeof(Float4);
        ky = std::size_t(r.shear.ky) * sizeof(Float4);
        kz = std::size_t(r.shear.kz) * sizeof(Float4);
        ox = splat(o[r.shear.kx]);
        oy = splat(o[r.shear.ky]);
        oz = splat(o[r.shear.kz]);
        sx = splat(r.shear.sx);
        sy = splat(r.shear.sy);
        sz = splat(r.shear.sz);
    }
};

// A row of four coordinates read in place (aligned: blocks are 16-byte aligned). may_alias: it
// reads floats. (A memcpy into a local went through the stack.)
typedef float Row __attribute__((vector_size(16), may_alias));

[[gnu::always_inline]] inline Float4 row(const TriangleBlock& b, int corner, std::size_t axis) {
    return *reinterpret_cast<const Row*>(reinterpret_cast<const char*>(b.v[corner]) + axis);
}

// Edge function `edge` (the one opposite that corner) again from exact products in double, in
// the lanes of `lanes` where its float value w is 0 (as edge_function in watertight_triangle.cpp
// does). Rare: rays through edges. It shears the corners again itself, and takes and returns w
// by value, so that the common path keeps everything in registers.
Float4 exact_zero_edge(unsigned lanes, const TriangleBlock& b, const Ray4& r, Float4 w, int edge);

// The lanes hit within [t_min, t_max] (bit k for lane k), with their t, u and v. Each lane's
// operations are intersect_watertight's, in the same order, so the results are the same bits.
[[gnu::always_inline]] inline unsigned candidates(const TriangleBlock& b, const Ray4& r,
                                                  Interval t_range, Float4& t, Float4& u,
                                                  Float4& v) {
    Float4 x[3], y[3], z[3];
    for (int c = 0; c < 3; ++c) {
        z[c] = row(b, c, r.kz) - r.oz;
        x[c] = (row(b, c, r.kx) - r.ox) - r.sx * z[c];
        y[c] = (row(b, c, r.ky) - r.oy) - r.sy * z[c];
    }
    // w[i] is the edge function opposite corner i: det times its barycentric weight.
    Float4 w[3] = {x[2] * y[1] - y[2] * x[1], x[0] * y[2] - y[0] * x[2], x[1] * y[0] - y[1] * x[0]};
    const Float4 zero = splat(0);
    for (int i = 0; i < 3; ++i)
        if (const unsigned exact = mask_of(w[i] == zero))
            w[i] = exact_zero_edge(exact, b, r, w[i], i);
    const Int4 negative = (w[0] < zero) | (w[1] < zero) | (w[2] < zero);
    const Int4 positive = (w[0] > zero) | (w[1] > zero) | (w[2] > zero);
    const Float4 det = w[0] + w[1] + w[2];
    const Float4 abs_det = abs(det);
    const Float4 inf = splat(kInfinity);
    Int4 ok = ~(negative & positive) & (det != zero) & (abs_det < inf);
    if (mask_of(ok) == 0) return 0;

    const Float4 t_scaled = r.sz * (w[0] * z[0] + w[1] * z[1] + w[2] * z[2]);
    const Float4 signed_t = det < zero ? -t_scaled : t_scaled;
    constexpr float kTiny = std::numeric_limits<float>::min();
    if (t_range.max >= kTiny) {
        const Float4 far = splat(t_range.max) * abs_det;
        ok &= ~(signed_t > far + far * splat(0x1p-20f) + splat(kTiny));
        if (mask_of(ok) == 0) return 0;
    }
    const Float4 inv_det = splat(1) / det;
    t = t_scaled * inv_det;
    ok &= (abs(t) < inf) & (splat(t_range.min) <= t) & (t <= splat(t_range.max));
    u = w[1] * inv_det;
    v = w[2] * inv_det;
    return mask_of(ok);
}

}  // namespace block_simd

#endif

// One ray's block tests on the path a traversal runs: kSimd picks the SIMD form where this build
// has one. accept(lane) says whether a lane may be hit at all (a visibility mask, say); it is
// asked only about lanes the ray hits.
class BlockTester {
    // Lane k by the scalar watertight test. Above the templates that call it: clang must know a
    // deduced return type where it is used.
    auto scalar_hit(const TriangleBlock& b, Interval t_range) const {
        return [&b, t_range, this](int k) {
            const auto hit = intersect_watertight(b.corner(k, 0), b.corner(k, 1), b.corner(k, 2),
                                                  ray_.ray, ray_.shear, t_range);
            return hit ? BlockHit{hit->t, hit->u, hit->v, k} : BlockHit{};
        };
    }

public:
    explicit BlockTester(const Ray& ray)
        : ray_(ray)
#ifdef GLINT_TRIANGLE_BLOCK_HAS_SIMD
          ,
          ray4_(ray_)
#endif
    {
    }

    // The nearest accepted hit within t_range, the lowest lane at equal t.
    template <bool kSimd, typename Accept>
    [[gnu::always_inline]] BlockHit nearest(const TriangleBlock& b, Interval t_range,
                                            Accept&& accept) const {
        if constexpr (kCountTraversal) count_primitives(unsigned(std::popcount(used_lanes(b))));
#ifdef GLINT_TRIANGLE_BLOCK_HAS_SIMD
        if constexpr (kSimd) {
            block_simd::Float4 t, u, v;
            const unsigned lanes = block_simd::candidates(b, ray4_, t_range, t, u, v);
            return nearest_lane(
                lanes,
                [&](int k) {
                    return BlockHit{t[k], u[k], v[k], k};
                },
                accept);
        }
#endif
        return nearest_lane(used_lanes(b), scalar_hit(b, t_range), accept);
    }

    // Whether an accepted lane is hit within t_range.
    template <bool kSimd, typename Accept>
    [[gnu::always_inline]] bool any(const TriangleBlock& b, Interval t_range,
                                    Accept&& accept) const {
        if constexpr (kCountTraversal) count_primitives(unsigned(std::popcount(used_lanes(b))));
#ifdef GLINT_TRIANGLE_BLOCK_HAS_SIMD
        if constexpr (kSimd) {
            block_simd::Float4 t, u, v;
            const unsigned lanes = block_simd::candidates(b, ray4_, t_range, t, u, v);
            return any_lane(
                lanes,
                [&](int k) {
                    return BlockHit{t[k], u[k], v[k], k};
                },
                accept);
        }
#endif
        return any_lane(used_lanes(b), scalar_hit(b, t_range), accept);
    }

private:
    static unsigned used_lanes(const TriangleBlock& b) {
        unsigned lanes = 0;
        for (int k = 0; k < 4; ++k) lanes |= unsigned(b.id[k] != kNoTriangle) << k;
        return lanes;
    }

    BlockRay ray_;
#ifdef GLINT_TRIANGLE_BLOCK_HAS_SIMD
    block_simd::Ray4 ray4_;
#endif
};

}  // namespace glint
