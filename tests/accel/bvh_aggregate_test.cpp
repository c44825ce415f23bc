// The scene-level BVH returns exactly the brute-force list's closest hits and occlusion answers.
#include "glint/accel/bvh_aggregate.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "glint/accel/primitive_list.h"

namespace glint {
namespace {

std::vector<Primitive> random_scene(int n, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> pos(-10, 10), size(0.05f, 1.5f), unit(0, 1);
    std::vector<Primitive> prims;
    for (int i = 0; i < n; ++i) {
        const Point3 c{pos(rng), pos(rng), pos(rng)};
        const float s = size(rng);
        Primitive p;
        switch (i % 3) {
            case 0:
                p.shape = Sphere{c, s};
                break;
            case 1:
                p.shape = Box{c, c + Vector3{s, s * 0.5f, s * 2}};
                break;
            default:
                p.shape = Triangle{{c, c + Vector3{s, 0, 0}, c + Vector3{0, s, s}}};
        }
        if (unit(rng) < 0.2f) p.visibility = kVisibleToCameraRays;  // casts no shadow
        prims.push_back(p);
    }
    prims.push_back({Plane{{0, -11, 0}, {0, 1, 0}}});
    return prims;
}

TEST(BvhAggregate, AgreesWithBruteForceOnRandomAndAxisParallelRays) {
    const auto prims = random_scene(3000, 3);
    const BvhAggregate bvh(prims);
    const PrimitiveList list(prims);
    std::mt19937 rng(4);
    std::uniform_real_distribution<float> u(-1, 1);
    int hits = 0;
    for (int i = 0; i < 3000; ++i) {
        Vector3 d{u(rng), u(rng), u(rng)};
        if (i % 10 == 0) d = {0, 0, u(rng) < 0 ? -1.0f : 1.0f};  // axis-parallel
        if (length_squared(d) < 1e-4f) continue;
        const Ray ray{{u(rng) * 12, u(rng) * 12, u(rng) * 12}, normalize(d)};
        for (const std::uint32_t mask :
             {std::uint32_t(kVisibleToCameraRays), std::uint32_t(kVisibleToShadowRays)}) {
            const auto a = bvh.intersect(ray, {}, mask);
            const auto b = list.intersect(ray, {}, mask);
            ASSERT_EQ(a.has_value(), b.has_value()) << "ray " << i;
            if (a) {
                ++hits;
                EXPECT_EQ(a->shape_hit.t, b->shape_hit.t) << "ray " << i;
                EXPECT_EQ(a->primitive, b->primitive) << "ray " << i;
            }
            const Interval segment{0, 5};
            EXPECT_EQ(bvh.occluded(ray, segment, mask), list.occluded(ray, segment, mask))
                << "ray " << i;
        }
    }
    EXPECT_GT(hits, 1000);
}

TEST(BvhAggregate, BoundsLeaveOutPlanesAndEmptySceneHitsNothing) {
    const std::vector<Primitive> prims{{Sphere{{1, 2, 3}, 1}}, {Plane{}}};
    const BvhAggregate bvh(prims);
    EXPECT_EQ(bvh.bounds().min, (Point3{0, 1, 2}));
    EXPECT_TRUE(bvh.intersect({{0, 5, 0}, {0, -1, 0}}, {}, ~0u));  // the plane
    const BvhAggregate empty({});
    EXPECT_FALSE(empty.intersect({{0, 0, 0}, {0, 0, 1}}, {}, ~0u));
    EXPECT_FALSE(empty.occluded({{0, 0, 0}, {0, 0, 1}}, {}, ~0u));
}

TEST(BvhAggregate, ManyCoincidentPrimitivesBuildAndHit) {
    std::vector<Primitive> prims(20000, Primitive{Sphere{{0, 0, 5}, 1}});
    const BvhAggregate bvh(prims);
    const auto hit = bvh.intersect({{0, 0, 0}, {0, 0, 1}}, {}, ~0u);
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit->shape_hit.t, 4);
}

}  // namespace
}  // namespace glint
