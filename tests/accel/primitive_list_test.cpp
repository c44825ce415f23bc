#include "glint/accel/primitive_list.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "glint/accel/make_aggregate.h"

namespace glint {
namespace {

std::vector<Primitive> random_spheres_and_triangles(int n, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> pos(-5, 5), size(0.1f, 1);
    std::vector<Primitive> prims;
    for (int i = 0; i < n; ++i) {
        const Point3 c{pos(rng), pos(rng), pos(rng)};
        if (i % 2 == 0) {
            prims.push_back({Sphere{c, size(rng)}});
        } else {
            const float s = size(rng);
            prims.push_back({Triangle{{c, c + Vector3{s, 0, 0}, c + Vector3{0, s, s}}}});
        }
    }
    prims.push_back({Plane{{0, -6, 0}, {0, 1, 0}}});
    return prims;
}

TEST(PrimitiveList, ClosestHitIsTheMinimumOverAllPrimitives) {
    const auto prims = random_spheres_and_triangles(60, 1);
    const PrimitiveList list(prims);
    std::mt19937 rng(2);
    std::uniform_real_distribution<float> u(-1, 1);
    int hits = 0;
    for (int i = 0; i < 500; ++i) {
        const Ray ray{{u(rng) * 8, u(rng) * 8, u(rng) * 8},
                      normalize(Vector3{u(rng), u(rng), u(rng) + 0.001f})};
        float best = kInfinity;
        for (const Primitive& p : prims)
            if (const auto h = intersect(p.shape, ray, {})) best = std::min(best, h->t);
        const auto hit = list.intersect(ray, {}, kVisibleToCameraRays);
        ASSERT_EQ(hit.has_value(), best < kInfinity);
        if (!hit) continue;
        ++hits;
        EXPECT_EQ(hit->shape_hit.t, best);
        EXPECT_EQ(intersect(prims[hit->primitive].shape, ray, {})->t, best);
        EXPECT_TRUE(list.occluded(ray, {0, best * 1.001f}, kVisibleToCameraRays));
        EXPECT_FALSE(list.occluded(ray, {0, best * 0.999f}, kVisibleToCameraRays));
    }
    EXPECT_GT(hits, 100);
}

TEST(PrimitiveList, RayMaskSkipsPrimitivesInvisibleToIt) {
    std::vector<Primitive> prims{{Sphere{{0, 0, 5}, 1}, kVisibleToCameraRays},
                                 {Sphere{{0, 0, 10}, 1}}};
    const PrimitiveList list(prims);
    const Ray ray{{0, 0, 0}, {0, 0, 1}};
    EXPECT_EQ(list.intersect(ray, {}, kVisibleToCameraRays)->primitive, 0u);
    EXPECT_EQ(list.intersect(ray, {}, kVisibleToShadowRays)->primitive, 1u);
    EXPECT_FALSE(list.occluded(ray, {0, 8}, kVisibleToShadowRays));
    EXPECT_TRUE(list.occluded(ray, {0, 8}, kVisibleToCameraRays));
}

TEST(PrimitiveList, BoundsLeaveOutUnboundedPrimitives) {
    std::vector<Primitive> prims{{Sphere{{1, 2, 3}, 1}}, {Plane{}}};
    const Bounds3 b = make_aggregate(AccelKind::list, prims)->bounds();
    EXPECT_EQ(b.min, (Point3{0, 1, 2}));
    EXPECT_EQ(b.max, (Point3{2, 3, 4}));
}

TEST(PrimitiveList, EmptyListHitsNothing) {
    const PrimitiveList list({});
    EXPECT_FALSE(list.intersect({{0, 0, 0}, {0, 0, 1}}, {}, ~0u));
    EXPECT_FALSE(list.occluded({{0, 0, 0}, {0, 0, 1}}, {}, ~0u));
    EXPECT_TRUE(list.bounds().is_empty());
}

}  // namespace
}  // namespace glint
