// Triangle blocks: every lane of a block test, on every path, reports exactly what the scalar
// watertight test reports for that lane's triangle; unused lanes and degenerate triangles are
// never hit; the nearest lane wins, the lowest at equal t; rejected lanes are skipped.
#include "glint/geometry/triangle_block.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>

#include "glint/geometry/simd_path.h"

namespace glint {
namespace {

struct Corners {
    Point3 v0, v1, v2;
};

// The block test on the path `simd` names (the SIMD form only where this build has one).
template <bool kSimd>
BlockHit nearest(const BlockTester& tester, const TriangleBlock& b, Interval range) {
    return tester.nearest<kSimd>(b, range, kEveryLane);
}

#ifdef GLINT_TRIANGLE_BLOCK_HAS_SIMD
// The SIMD form as the AVX2 traversal compiles it (VEX encoding, the same operations).
__attribute__((target("avx2"))) BlockHit nearest_avx2(const BlockTester& tester,
                                                      const TriangleBlock& b, Interval range) {
    return tester.nearest<true>(b, range, kEveryLane);
}
#endif

// Each lane alone: the block holds only it, so nearest() reports that lane's own hit.
void expect_lane_equals_scalar(const Corners& c, const Ray& ray, Interval range, int lane) {
    TriangleBlock block = empty_triangle_block();
    set_block_lane(block, lane, c.v0, c.v1, c.v2, 7);
    const auto expected = intersect_watertight(c.v0, c.v1, c.v2, ray, range);
    const BlockTester tester(ray);
    std::vector<BlockHit> got{nearest<false>(tester, block, range),
                              nearest<true>(tester, block, range)};
#ifdef GLINT_TRIANGLE_BLOCK_HAS_SIMD
    if (simd_path_supported(SimdPath::avx2)) got.push_back(nearest_avx2(tester, block, range));
#endif
    for (const auto& hit : got) {
        ASSERT_EQ(bool(hit), expected.has_value());
        if (!hit) continue;
        EXPECT_EQ(hit.lane, lane);
        // Bit for bit: the same operations in the same order.
        EXPECT_EQ(std::bit_cast<std::uint32_t>(hit.t), std::bit_cast<std::uint32_t>(expected->t));
        EXPECT_EQ(std::bit_cast<std::uint32_t>(hit.u), std::bit_cast<std::uint32_t>(expected->u));
        EXPECT_EQ(std::bit_cast<std::uint32_t>(hit.v), std::bit_cast<std::uint32_t>(expected->v));
    }
}

TEST(TriangleBlock, EveryLaneEqualsTheScalarTestOnRandomAndEdgeAimedRays) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(-1, 1);
    int hits = 0;
    for (int i = 0; i < 4000; ++i) {
        const float scale = std::pow(10.0f, float(i % 5) - 2);
        const Corners c{{u(rng) * scale, u(rng) * scale, u(rng) * scale},
                        {u(rng) * scale, u(rng) * scale, u(rng) * scale},
                        {u(rng) * scale, u(rng) * scale, u(rng) * scale}};
        const Point3 origin{u(rng) * 3 * scale, u(rng) * 3 * scale, u(rng) * 3 * scale};
        // At a vertex, exactly at an edge's midpoint (the exact fallback), or anywhere.
        const Point3 aim = i % 3 == 0   ? c.v1
                           : i % 3 == 1 ? c.v0 + (c.v2 - c.v0) * 0.5f
                                        : c.v0 + (c.v1 - c.v0) * (0.5f + 0.5f * u(rng));
        if (distance(aim, origin) == 0) continue;
        const Ray ray{origin, normalize(aim - origin)};
        const Interval range = i % 4 == 0 ? Interval{0, distance(aim, origin)} : Interval{};
        for (int lane = 0; lane < 4; ++lane) expect_lane_equals_scalar(c, ray, range, lane);
        hits += intersect_watertight(c.v0, c.v1, c.v2, ray, range).has_value();
    }
    EXPECT_GT(hits, 1000);
}

TEST(TriangleBlock, RaysAlongTheAxesWithSignedZerosEqualTheScalarTest) {
    const Corners c{{-1, -1, 2}, {1, -1, 2}, {0, 1, 2}};
    for (const Vector3 d : {Vector3{0, 0, 1}, Vector3{-0.0f, 0, 1}, Vector3{0, -0.0f, -1},
                            Vector3{1, 0, -0.0f}, Vector3{0, 1, 0}}) {
        for (const Point3 o : {Point3{0, 0, 0}, Point3{0, -1, 0}, Point3{-1, -1, 0}})
            for (int lane = 0; lane < 4; ++lane) expect_lane_equals_scalar(c, {o, d}, {}, lane);
    }
}

TEST(TriangleBlock, UnusedLanesAndDegenerateTrianglesAreNeverHit) {
    TriangleBlock block = empty_triangle_block();
    for (const std::uint32_t id : block.id) EXPECT_EQ(id, kNoTriangle);
    // Collinear corners: intersect_watertight never hits them, so the lane stays unused.
    set_block_lane(block, 2, {0, 0, 0}, {1, 1, 1}, {2, 2, 2}, 5);
    EXPECT_EQ(block.id[2], kNoTriangle);
    const BlockTester tester(Ray{{0.5f, 0.5f, -1}, {0, 0, 1}});
    EXPECT_FALSE(nearest<false>(tester, block, {}));
    EXPECT_FALSE(nearest<true>(tester, block, {}));
}

TEST(TriangleBlock, TheNearestLaneWinsAndTheLowestAtEqualT) {
    TriangleBlock block = empty_triangle_block();
    const Ray ray{{0.2f, 0.2f, -1}, {0, 0, 1}};
    set_block_lane(block, 0, {0, 0, 3}, {1, 0, 3}, {0, 1, 3}, 10);  // t = 4
    set_block_lane(block, 1, {0, 0, 2}, {1, 0, 2}, {0, 1, 2}, 11);  // t = 3
    set_block_lane(block, 3, {0, 0, 2}, {1, 0, 2}, {0, 1, 2}, 13);  // the same: equal t
    const BlockTester tester(ray);
    for (const auto& hit : {nearest<false>(tester, block, {}), nearest<true>(tester, block, {})}) {
        ASSERT_TRUE(hit);
        EXPECT_EQ(hit.lane, 1);
        EXPECT_FLOAT_EQ(hit.t, 3);
    }
    // The range's far end drops the nearer ones only when it excludes them.
    const auto far_only = tester.nearest<true>(block, {3.5f, 10}, kEveryLane);
    ASSERT_TRUE(far_only);
    EXPECT_EQ(far_only.lane, 0);
    // A lane that is not accepted is passed over.
    const auto not_one = [](int lane) { return lane != 1; };
    for (const auto& hit :
         {tester.nearest<false>(block, {}, not_one), tester.nearest<true>(block, {}, not_one)}) {
        ASSERT_TRUE(hit);
        EXPECT_EQ(hit.lane, 3);
    }
    EXPECT_TRUE(tester.any<true>(block, {}, kEveryLane));
    EXPECT_FALSE(tester.any<true>(block, {}, [](int) { return false; }));
    EXPECT_FALSE(tester.any<false>(block, {0, 2.5f}, kEveryLane));
}

TEST(TriangleBlock, NanRaysHitNothing) {
    TriangleBlock block = empty_triangle_block();
    set_block_lane(block, 0, {-1, -1, 2}, {1, -1, 2}, {0, 1, 2}, 0);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    for (const Ray ray : {Ray{{nan, 0, 0}, {0, 0, 1}}, Ray{{0, 0, 0}, {0, nan, 1}},
                          Ray{{0, 0, 0}, {0, 0, kInfinity}}}) {
        const BlockTester tester(ray);
        EXPECT_FALSE(nearest<false>(tester, block, {}));
        EXPECT_FALSE(nearest<true>(tester, block, {}));
    }
}

}  // namespace
}  // namespace glint
