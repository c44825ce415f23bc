// Sphere blocks: every lane of a block test, on every path, reports exactly what
// Sphere::intersect reports for that lane's sphere; unused lanes are never hit; the nearest lane
// wins, the lowest at equal t; rejected lanes are skipped.
#include "glint/geometry/sphere_block.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "glint/geometry/simd_path.h"

namespace glint {
namespace {

#ifdef GLINT_SPHERE_BLOCK_HAS_SIMD
// The SIMD form as the AVX2 traversal compiles it.
__attribute__((target("avx2"))) BlockHit nearest_avx2(const SphereTester& tester,
                                                      const SphereBlock& b, Interval range) {
    return tester.nearest<true>(b, range, kEveryLane);
}
#endif

void expect_lane_equals_scalar(const Sphere& sphere, const Ray& ray, Interval range, int lane) {
    SphereBlock block = empty_sphere_block();
    set_sphere_lane(block, lane, sphere, 3);
    const auto expected = sphere.intersect(ray, range);
    const SphereTester tester(ray);
    std::vector<BlockHit> got{tester.nearest<false>(block, range, kEveryLane),
                              tester.nearest<true>(block, range, kEveryLane)};
#ifdef GLINT_SPHERE_BLOCK_HAS_SIMD
    if (simd_path_supported(SimdPath::avx2)) got.push_back(nearest_avx2(tester, block, range));
#endif
    for (const auto& hit : got) {
        ASSERT_EQ(bool(hit), expected.has_value());
        if (!hit) continue;
        EXPECT_EQ(hit.lane, lane);
        EXPECT_EQ(std::bit_cast<std::uint32_t>(hit.t), std::bit_cast<std::uint32_t>(expected->t));
    }
}

TEST(SphereBlock, EveryLaneEqualsTheGeometricTestOfTheNotes) {
    std::mt19937 rng(17);
    std::uniform_real_distribution<float> u(-1, 1), unit(0.01f, 1);
    int hits = 0;
    for (int i = 0; i < 4000; ++i) {
        const float scale = std::pow(10.0f, float(i % 5) - 2);
        const Sphere sphere{{u(rng) * scale, u(rng) * scale, u(rng) * scale}, unit(rng) * scale};
        // From outside, from inside, and grazing: aimed at the sphere's rim.
        const Point3 origin =
            i % 3 == 1 ? sphere.center + Vector3{0.1f, 0, 0} * sphere.radius
                       : Point3{u(rng) * 4 * scale, u(rng) * 4 * scale, u(rng) * 4 * scale};
        const Point3 aim = i % 3 == 2 ? sphere.center + Vector3{sphere.radius, 0, 0}
                                      : sphere.center + Vector3{u(rng), u(rng), u(rng)} * scale;
        if (distance(aim, origin) == 0) continue;
        const Ray ray{origin, normalize(aim - origin)};
        const Interval range = i % 4 == 0 ? Interval{0.5f * scale, 2 * scale} : Interval{};
        for (int lane = 0; lane < 4; ++lane) expect_lane_equals_scalar(sphere, ray, range, lane);
        hits += sphere.intersect(ray, range).has_value();
    }
    EXPECT_GT(hits, 1000);
}

TEST(SphereBlock, UnusedLanesAndNanRaysHitNothing) {
    SphereBlock block = empty_sphere_block();
    for (const std::uint32_t id : block.id) EXPECT_EQ(id, kNoSphere);
    const SphereTester empty({{0, 0, -5}, {0, 0, 1}});
    EXPECT_FALSE(empty.nearest<true>(block, {}, kEveryLane));
    set_sphere_lane(block, 1, Sphere{{0, 0, 0}, 1}, 0);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    for (const Ray ray : {Ray{{nan, 0, -5}, {0, 0, 1}}, Ray{{0, 0, -5}, {0, nan, 1}}}) {
        const SphereTester tester(ray);
        EXPECT_FALSE(tester.nearest<false>(block, {}, kEveryLane));
        EXPECT_FALSE(tester.nearest<true>(block, {}, kEveryLane));
    }
}

TEST(SphereBlock, TheNearestLaneWinsAndTheLowestAtEqualT) {
    SphereBlock block = empty_sphere_block();
    set_sphere_lane(block, 0, Sphere{{0, 0, 10}, 1}, 10);  // t = 14
    set_sphere_lane(block, 1, Sphere{{0, 0, 5}, 1}, 11);   // t = 9
    set_sphere_lane(block, 3, Sphere{{0, 0, 5}, 1}, 13);   // the same: equal t
    const SphereTester tester({{0, 0, -5}, {0, 0, 1}});
    for (const auto& hit : {tester.nearest<false>(block, {}, kEveryLane),
                            tester.nearest<true>(block, {}, kEveryLane)}) {
        ASSERT_TRUE(hit);
        EXPECT_EQ(hit.lane, 1);
        EXPECT_EQ(hit.t, 9);
    }
    const auto not_one = [](int lane) { return lane != 1; };
    EXPECT_EQ(tester.nearest<true>(block, {}, not_one).lane, 3);
    EXPECT_EQ(tester.nearest<true>(block, {12, 100}, kEveryLane).lane, 0);
    EXPECT_TRUE(tester.any<true>(block, {}, kEveryLane));
    EXPECT_FALSE(tester.any<true>(block, {0, 8}, kEveryLane));
    EXPECT_FALSE(tester.any<false>(block, {}, [](int) { return false; }));
}

}  // namespace
}  // namespace glint
