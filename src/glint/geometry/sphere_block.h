// Four spheres side by side, so that one SIMD pass runs the notes' geometric test
// (Sphere::intersect) on all of them: leaves of the scene's wide BVH. Every lane's answer is
// exactly Sphere::intersect's for that sphere.
#pragma once

#include <bit>
#include <cstdint>
#include <optional>

#include "glint/geometry/block_hit.h"
#include "glint/geometry/sphere.h"
#include "glint/geometry/traversal_counters.h"
#include "glint/math/interval.h"
#include "glint/math/ray.h"

namespace glint {

// The id of an unused lane.
inline constexpr std::uint32_t kNoSphere = 0xffffffffu;

struct alignas(16) SphereBlock {
    float center[3][4];  // center[axis][lane]
    float radius[4];
    // What the owner calls each lane's sphere. An unused lane has kNoSphere and a NaN centre,
    // which no ray hits.
    std::uint32_t id[4];

    Sphere sphere(int lane) const {
        return {{center[0][lane], center[1][lane], center[2][lane]}, radius[lane]};
    }
};
static_assert(sizeof(SphereBlock) == 80, "a cache line and a quarter");

// A block of four unused lanes.
SphereBlock empty_sphere_block();
void set_sphere_lane(SphereBlock& block, int lane, const Sphere& sphere, std::uint32_t id);

#if defined(__x86_64__) && defined(__GNUC__)
#define GLINT_SPHERE_BLOCK_HAS_SIMD 1

namespace sphere_simd {

typedef float Float4 __attribute__((vector_size(16)));
typedef int Int4 __attribute__((vector_size(16)));
// A row read in place (blocks are 16-byte aligned); may_alias: it reads floats.
typedef float Row __attribute__((vector_size(16), may_alias));

[[gnu::always_inline]] inline Float4 splat(float x) { return Float4{x, x, x, x}; }
[[gnu::always_inline]] inline Float4 row(const float* r) {
    return *reinterpret_cast<const Row*>(r);
}
[[gnu::always_inline]] inline unsigned mask_of(Int4 m) {
    return unsigned(__builtin_ia32_movmskps(reinterpret_cast<Float4>(m)));
}

struct Ray4 {
    Float4 ox, oy, oz, dx, dy, dz;

    explicit Ray4(const Ray& r)
        : ox(splat(r.origin.x)),
          oy(splat(r.origin.y)),
          oz(splat(r.origin.z)),
          dx(splat(r.direction.x)),
          dy(splat(r.direction.y)),
          dz(splat(r.direction.z)) {}
};

// The lanes hit within t_range (bit k for lane k) and their t: Sphere::intersect's steps, lane by
// lane, in the same order, so the results are the same bits.
[[gnu::always_inline]] inline unsigned candidates(const SphereBlock& b, const Ray4& r,
                                                  Interval t_range, Float4& t) {
    const Float4 cx = row(b.center[0]), cy = row(b.center[1]), cz = row(b.center[2]);
    const Float4 mx = cx - r.ox, my = cy - r.oy, mz = cz - r.oz;  // M - P0
    const Float4 m2 = mx * mx + my * my + mz * mz;                // 1. m^2
    const Float4 radius = row(b.radius);
    const Float4 r2 = radius * radius;
    const Float4 h = r.dx * mx + r.dy * my + r.dz * mz;  // 2. h = R.(M - P0)
    Int4 ok = ~((m2 > r2) & (h < splat(0)));             //    outside, pointing away: no hit
    if (mask_of(ok) == 0) return 0;
    // 3. D = P0 + h R; 4. d^2 = (M - D)^2
    const Float4 qx = cx - (r.ox + r.dx * h), qy = cy - (r.oy + r.dy * h),
                 qz = cz - (r.oz + r.dz * h);
    const Float4 d2 = qx * qx + qy * qy + qz * qz;
    ok &= ~(d2 > r2);  // 5. the ray passes by
    if (mask_of(ok) == 0) return 0;
    const Float4 s = __builtin_ia32_sqrtps(r2 - d2);  // 6. t1 = h - s, t2 = h + s
    const Float4 t1 = h - s, t2 = h + s;
    const Float4 lo = splat(t_range.min), hi = splat(t_range.max);
    const Int4 in1 = (lo <= t1) & (t1 <= hi), in2 = (lo <= t2) & (t2 <= hi);
    t = in1 ? t1 : t2;
    return mask_of(ok & (in1 | in2));
}

}  // namespace sphere_simd

#endif

// One ray's sphere-block tests on the path a traversal runs (kSimd), as BlockTester's for
// triangles; accept(lane) is asked only about lanes the ray hits.
class SphereTester {
    // Lane k by Sphere::intersect. Above the templates that call it: clang must know a deduced
    // return type where it is used.
    auto scalar_hit(const SphereBlock& b, Interval t_range) const {
        return [&b, t_range, this](int k) {
            const auto hit = b.sphere(k).intersect(ray_, t_range);
            return hit ? BlockHit{hit->t, 0, 0, k} : BlockHit{};
        };
    }

public:
    explicit SphereTester(const Ray& ray)
        : ray_(ray)
#ifdef GLINT_SPHERE_BLOCK_HAS_SIMD
          ,
          ray4_(ray)
#endif
    {
    }

    // The nearest accepted hit within t_range, the lowest lane at equal t.
    template <bool kSimd, typename Accept>
    [[gnu::always_inline]] BlockHit nearest(const SphereBlock& b, Interval t_range,
                                            Accept&& accept) const {
        if constexpr (kCountTraversal) count_primitives(unsigned(std::popcount(used_lanes(b))));
#ifdef GLINT_SPHERE_BLOCK_HAS_SIMD
        if constexpr (kSimd) {
            sphere_simd::Float4 t;
            const unsigned lanes = sphere_simd::candidates(b, ray4_, t_range, t);
            return nearest_lane(
                lanes,
                [&](int k) {
                    return BlockHit{t[k], 0, 0, k};
                },
                accept);
        }
#endif
        return nearest_lane(used_lanes(b), scalar_hit(b, t_range), accept);
    }

    // Whether an accepted lane is hit within t_range.
    template <bool kSimd, typename Accept>
    [[gnu::always_inline]] bool any(const SphereBlock& b, Interval t_range, Accept&& accept) const {
        if constexpr (kCountTraversal) count_primitives(unsigned(std::popcount(used_lanes(b))));
#ifdef GLINT_SPHERE_BLOCK_HAS_SIMD
        if constexpr (kSimd) {
            sphere_simd::Float4 t;
            const unsigned lanes = sphere_simd::candidates(b, ray4_, t_range, t);
            return any_lane(
                lanes,
                [&](int k) {
                    return BlockHit{t[k], 0, 0, k};
                },
                accept);
        }
#endif
        return any_lane(used_lanes(b), scalar_hit(b, t_range), accept);
    }

private:
    static unsigned used_lanes(const SphereBlock& b) {
        unsigned lanes = 0;
        for (int k = 0; k < 4; ++k) lanes |= unsigned(b.id[k] != kNoSphere) << k;
        return lanes;
    }

    Ray ray_;
#ifdef GLINT_SPHERE_BLOCK_HAS_SIMD
    sphere_simd::Ray4 ray4_;
#endif
};

}  // namespace glint
