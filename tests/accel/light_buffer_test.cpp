// The light buffer answers exactly as the brute-force list for feelers towards its light, and
// its cells hold every primitive that can block them.
#include "glint/accel/light_buffer.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "glint/accel/primitive_list.h"

namespace glint {
namespace {

std::vector<Primitive> random_occluders(int n, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> pos(-6, 6), size(0.05f, 1.2f), unit(0, 1);
    std::vector<Primitive> prims;
    for (int i = 0; i < n; ++i) {
        const Point3 c{pos(rng), pos(rng), pos(rng)};
        const float s = size(rng);
        Primitive p;
        if (i % 3 == 0) p.shape = Sphere{c, s};
        if (i % 3 == 1) p.shape = Box{c, c + Vector3{s, 2 * s, s * 0.5f}};
        if (i % 3 == 2) p.shape = Triangle{{c, c + Vector3{s, 0, 0}, c + Vector3{0, s, s}}};
        if (unit(rng) < 0.1f) p.visibility = kVisibleToCameraRays;  // casts no shadow
        prims.push_back(p);
    }
    prims.push_back({Plane{{0, -7, 0}, {0, 1, 0}}});
    return prims;
}

// A feeler from p to the light, as the integrator makes them.
std::pair<Ray, Interval> feeler(Point3 p, Point3 light) {
    const Vector3 d = light - p;
    const float l = length(d);
    return {Ray{p, d / l}, Interval{0, l}};
}

// min_answered: how many of the 3000 feelers the buffer must answer itself (the rest fall in
// crowded cells).
void expect_same_answers(Point3 light, int resolution, unsigned seed, int occluders,
                         int min_answered) {
    const auto prims = random_occluders(occluders, seed);
    const LightBuffer buffer(light, prims, resolution);
    const PrimitiveList list(prims);
    std::mt19937 rng(seed + 1);
    std::uniform_real_distribution<float> pos(-8, 8);
    int blocked = 0, answered = 0;
    std::uint32_t hint = LightBuffer::kNoPrimitive;
    for (int i = 0; i < 3000; ++i) {
        const Point3 p{pos(rng), pos(rng), pos(rng)};
        const auto [ray, range] = feeler(p, light);
        const bool expected = list.occluded(ray, range, kVisibleToShadowRays);
        // A crowded cell leaves the answer to the acceleration structure.
        const auto answer = buffer.occluded(ray, range, hint);
        ASSERT_EQ(answer.value_or(expected), expected) << "point " << i;
        answered += answer.has_value();
        blocked += expected;
    }
    EXPECT_GT(blocked, 300);
    EXPECT_LT(blocked, 2700);
    EXPECT_GE(answered, min_answered);
}

TEST(LightBuffer, AgreesWithBruteForceForALightOutsideTheScene) {
    expect_same_answers({3, 15, -4}, 0, 1, 1500, 100);
}

TEST(LightBuffer, AgreesWithBruteForceForALightAmongTheObjects) {
    expect_same_answers({0.3f, 0.2f, -0.1f}, 16, 2, 200, 1500);
    expect_same_answers({1, 1, 1}, 3, 3, 200, 0);  // coarse cells: mostly crowded
}

TEST(LightBuffer, TheOccluderFoundIsRememberedAndTestedFirst) {
    const std::vector<Primitive> prims{{Sphere{{0, 5, 0}, 1}}, {Sphere{{5, 5, 0}, 1}}};
    const LightBuffer buffer({0, 10, 0}, prims);
    std::uint32_t hint = LightBuffer::kNoPrimitive;
    const auto [ray, range] = feeler({0, 0, 0}, {0, 10, 0});
    EXPECT_EQ(buffer.occluded(ray, range, hint), std::optional<bool>(true));
    EXPECT_EQ(hint, 0u);
    const auto [clear, clear_range] = feeler({-5, 0, 0}, {0, 10, 0});
    EXPECT_EQ(buffer.occluded(clear, clear_range, hint), std::optional<bool>(false));
}

TEST(LightBuffer, CellsListOnlyWhatLiesInTheirDirections) {
    // Two small spheres, one above the light and one below: a direction only meets one.
    const std::vector<Primitive> prims{{Sphere{{0, 5, 0}, 0.5f}}, {Sphere{{0, -5, 0}, 0.5f}}};
    const LightBuffer buffer({0, 0, 0}, prims, 8);
    const auto up = buffer.candidates({0, 1, 0});
    ASSERT_EQ(up.size(), 1u);
    EXPECT_EQ(up[0], 0u);
    const auto down = buffer.candidates({0.01f, -1, 0});
    ASSERT_EQ(down.size(), 1u);
    EXPECT_EQ(down[0], 1u);
    EXPECT_TRUE(buffer.candidates({1, 0, 0}).empty());
}

TEST(LightBuffer, AShapeAroundTheLightIsInEveryCell) {
    const std::vector<Primitive> prims{{Sphere{{0, 0, 0}, 2}}};
    const LightBuffer buffer({0.5f, 0, 0}, prims, 4);
    for (const Vector3 d : {Vector3{1, 0, 0}, Vector3{-1, 0.2f, 0}, Vector3{0, 0, -1}})
        EXPECT_EQ(buffer.candidates(d).size(), 1u);
}

// A flat grid of 2 n^2 triangles in the plane y = 0, from (-1, 0, -1) to (1, 0, 1), shifted by c.
Primitive grid_mesh(int n, Vector3 c) {
    MeshData arrays;
    for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j)
            arrays.positions.push_back(
                to_point(c + Vector3{-1 + 2 * float(i) / n, 0, -1 + 2 * float(j) / n}));
    const auto at = [&](int i, int j) { return std::uint32_t(i * (n + 1) + j); };
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            arrays.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            arrays.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    const MeshBuild built = build_mesh(std::move(arrays));
    return {TriangleMesh{built.mesh}};
}

TEST(LightBuffer, AMeshOfManyTrianglesLeavesItsCellsToTheStructure) {
    // A big mesh below the light, a small one (2 triangles) to the side, a sphere above.
    const std::vector<Primitive> prims{
        grid_mesh(8, {0, -2, 0}), grid_mesh(1, {5, 1, 0}), {Sphere{{0, 5, 0}, 0.5f}}};
    EXPECT_FALSE(LightBuffer::tests_whole(prims[0].shape));
    EXPECT_TRUE(LightBuffer::tests_whole(prims[1].shape));
    const LightBuffer buffer({0, 0, 0}, prims, 8);
    std::uint32_t hint = LightBuffer::kNoPrimitive;
    // Below: the big mesh's cells are crowded, whatever their lists.
    const auto [down, down_range] = feeler({0.1f, -4, 0.1f}, {0, 0, 0});
    EXPECT_FALSE(buffer.occluded(down, down_range, hint).has_value());
    EXPECT_TRUE(buffer.candidates({0.1f, -1, 0.1f}).empty());
    // The small mesh is listed and tested whole; the sphere too.
    const auto [side, side_range] = feeler({10, 2, 0}, {0, 0, 0});  // through (5, 1, 0)
    EXPECT_EQ(buffer.occluded(side, side_range, hint), std::optional<bool>(true));
    EXPECT_EQ(hint, 1u);
    const auto [up, up_range] = feeler({0, 10, 0}, {0, 0, 0});
    EXPECT_EQ(buffer.occluded(up, up_range, hint), std::optional<bool>(true));
    EXPECT_EQ(hint, 2u);
}

}  // namespace
}  // namespace glint
