// The benchmark ray sets: sizes, determinism, and where the secondary rays start and point.
#include "glint/render/ray_sets.h"

#include <gtest/gtest.h>

#include "glint/scene/yaml/yaml_scene_loader.h"

namespace glint {
namespace {

World showcase() {
    return World(load_yaml_scene(std::string(GLINT_SOURCE_DIR) + "/scenes/showcase.yaml"));
}

TEST(RaySets, ThreeEqualSetsThroughAScaledImage) {
    const World world = showcase();
    const RaySets sets = make_ray_sets(world, 1200);
    // The showcase is 4:3: 40 x 30 pixels make 1200 rays.
    EXPECT_EQ(sets.width, 40);
    EXPECT_EQ(sets.height, 30);
    ASSERT_EQ(sets.sets.size(), 3u);
    EXPECT_EQ(sets.sets[0].name, "primary");
    EXPECT_EQ(sets.sets[1].name, "incoherent");
    EXPECT_EQ(sets.sets[2].name, "shadow");
    for (const RaySet& set : sets.sets) EXPECT_EQ(set.rays.size(), 1200u) << set.name;
    EXPECT_EQ(sets.sets[2].query, RayQuery::occluded);
    EXPECT_EQ(sets.sets[2].mask, kVisibleToShadowRays);
    EXPECT_GT(sets.surface_points, 600u);  // the floor fills the lower half and more
    EXPECT_LE(sets.surface_points, 1200u);
}

TEST(RaySets, SameSeedSameRaysOtherSeedOtherDirections) {
    const World world = showcase();
    const RaySets a = make_ray_sets(world, 500, 7), b = make_ray_sets(world, 500, 7);
    const RaySets c = make_ray_sets(world, 500, 8);
    for (std::size_t s = 0; s < 3; ++s) {
        for (std::size_t i = 0; i < a.sets[s].rays.size(); ++i) {
            EXPECT_EQ(a.sets[s].rays[i].origin, b.sets[s].rays[i].origin);
            EXPECT_EQ(a.sets[s].rays[i].direction, b.sets[s].rays[i].direction);
        }
    }
    int differ = 0;
    for (std::size_t i = 0; i < a.sets[1].rays.size(); ++i)
        differ += a.sets[1].rays[i].direction != c.sets[1].rays[i].direction;
    EXPECT_GT(differ, 450);
}

// Incoherent rays leave on the side the eye came from; shadow feelers end at the first light.
TEST(RaySets, SecondaryRaysLeaveTheSurfaceTowardsTheEyeSideAndTheLight) {
    const World world = showcase();
    const RaySets sets = make_ray_sets(world, 2000);
    const Point3 light = std::get<PointLight>(world.lights().front()).position;
    const RaySet& primary = sets.sets[0];
    std::size_t start = 0;
    for (std::size_t i = 0; i < primary.rays.size(); ++i) {
        const Ray& eye = primary.rays[i];
        const auto hit = world.intersect(eye, {}, kVisibleToCameraRays);
        if (!hit) continue;
        const SurfacePoint sp = world.surface_at(eye, *hit);
        const Normal3 facing = face_forward(sp.normal, -eye.direction);
        const Ray& out = sets.sets[1].rays[start];
        EXPECT_NEAR(length(out.direction), 1, 1e-5f);
        EXPECT_GE(dot(facing, out.direction), 0) << "ray " << i;
        EXPECT_LT(distance(out.origin, sp.p), 1e-2f);

        const Ray& feeler = sets.sets[2].rays[start];
        const Interval range = sets.sets[2].range(start);
        // The offset origin moves the end by about the offset: within 1e-2 of a light 15 away.
        EXPECT_NEAR(distance(feeler.at(range.max), light), 0, 1e-2f) << "ray " << i;
        ++start;
    }
    EXPECT_EQ(start, sets.surface_points);
}

}  // namespace
}  // namespace glint
