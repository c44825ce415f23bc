// The uniform grid: resolution from primitive density, 3D-DDA stepping with worked numbers,
// mailboxing, and its cell lists on flat, coincident and mixed scenes.
#include "glint/accel/grid_aggregate.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "glint/accel/mailbox.h"

namespace glint {
namespace {

using Resolution = std::array<int, 3>;

TEST(GridResolution, CubeOfSixtyFourPrimitivesAtOneCellEachIsFourCubed) {
    // cells per axis = 4 * cbrt(1 * 64 / 64) = 4.
    EXPECT_EQ(grid_resolution({4, 4, 4}, 64, 1), (Resolution{4, 4, 4}));
    // 10 * cbrt(1000 / 1000) = 10; with density 3: 10 * cbrt(3) = 14.4 -> 14.
    EXPECT_EQ(grid_resolution({10, 10, 10}, 1000, 1), (Resolution{10, 10, 10}));
    EXPECT_EQ(grid_resolution({10, 10, 10}, 1000, 3), (Resolution{14, 14, 14}));
}

TEST(GridResolution, CellsStayCubicalOnLongBoxes) {
    // cbrt(16 / (2 * 1 * 1)) = 2 cells per unit: 4 x 2 x 2.
    EXPECT_EQ(grid_resolution({2, 1, 1}, 16, 1), (Resolution{4, 2, 2}));
}

TEST(GridResolution, FlatAxisGetsOneCellAndTheOthersShareTheBudget) {
    // y is (nearly) flat: x and z share 16 cells, sqrt(16 / (8 * 2)) = 1 per unit: 8 x 1 x 2.
    EXPECT_EQ(grid_resolution({8, 1e-6f, 2}, 16, 1), (Resolution{8, 1, 2}));
    // A thin rod: y and z would get 0.46 cells each (cbrt(10 / 100)), so x takes all 10.
    EXPECT_EQ(grid_resolution({100, 1, 1}, 10, 1), (Resolution{10, 1, 1}));
}

TEST(GridResolution, ZeroOrOnePrimitiveIsOneCell) {
    EXPECT_EQ(grid_resolution({3, 1, 2}, 0, 4), (Resolution{1, 1, 1}));
    EXPECT_EQ(grid_resolution({1, 1, 1}, 1, 1), (Resolution{1, 1, 1}));
}

struct Visited {
    std::uint32_t cell;
    Interval t;
};

std::vector<Visited> walk(const GridLayout& grid, const Ray& ray, Interval range = {}) {
    std::vector<Visited> cells;
    walk_grid(grid, ray, range, [&](std::uint32_t cell, Interval t) {
        cells.push_back({cell, t});
        return cells.size() < 1000;
    });
    return cells;
}

std::vector<std::uint32_t> indices(const std::vector<Visited>& visited) {
    std::vector<std::uint32_t> out;
    for (const Visited& v : visited) out.push_back(v.cell);
    return out;
}

const GridLayout kFourCubed = GridLayout::of({{0, 0, 0}, {4, 4, 4}}, {4, 4, 4});

TEST(WalkGrid, RayAlongXVisitsOneRowOfFourCells) {
    // From x = -1 at y = 0.5, z = 2.5: row y = 0, z = 2, whose cells are (2 * 4 + 0) * 4 + x.
    const auto visited = walk(kFourCubed, {{-1, 0.5f, 2.5f}, {1, 0, 0}});
    EXPECT_EQ(indices(visited), (std::vector<std::uint32_t>{32, 33, 34, 35}));
    ASSERT_EQ(visited.size(), 4u);
    for (int x = 0; x < 4; ++x) {
        EXPECT_FLOAT_EQ(visited[std::size_t(x)].t.min, float(x + 1));  // enters at x
        EXPECT_FLOAT_EQ(visited[std::size_t(x)].t.max, float(x + 2));  // leaves at x + 1
    }
}

TEST(WalkGrid, RayAlongMinusXVisitsTheRowBackwards) {
    const auto visited = walk(kFourCubed, {{5, 3.5f, 0.5f}, {-1, 0, 0}});
    EXPECT_EQ(indices(visited), (std::vector<std::uint32_t>{15, 14, 13, 12}));
}

TEST(WalkGrid, DiagonalRayAlternatesAxesInCrossingOrder) {
    // From (0.5, 0.25) along (1, 1)/sqrt 2: x planes at t = (k - 0.5) sqrt 2, y planes at
    // t = (k - 0.25) sqrt 2, so x, y, x, y, x, y: cells (0,0) (1,0) (1,1) (2,1) (2,2) (3,2) (3,3).
    const Ray ray{{0.5f, 0.25f, 0.5f}, normalize(Vector3{1, 1, 0})};
    const auto visited = walk(kFourCubed, ray);
    EXPECT_EQ(indices(visited), (std::vector<std::uint32_t>{0, 1, 5, 6, 10, 11, 15}));
    ASSERT_EQ(visited.size(), 7u);
    EXPECT_FLOAT_EQ(visited[1].t.min, 0.5f * std::sqrt(2.0f));
    EXPECT_FLOAT_EQ(visited[2].t.min, 0.75f * std::sqrt(2.0f));
    EXPECT_NEAR(visited[6].t.max, 3.5f * std::sqrt(2.0f), 1e-5);  // leaves the grid at x = 4
}

TEST(WalkGrid, IntervalEndingInsideStopsInItsCell) {
    const auto visited = walk(kFourCubed, {{0.5f, 0.5f, 0.5f}, {1, 0, 0}}, {0, 2.2f});
    EXPECT_EQ(indices(visited), (std::vector<std::uint32_t>{0, 1, 2}));
    EXPECT_FLOAT_EQ(visited.back().t.max, 2.2f);
}

TEST(WalkGrid, RayStartingOnTheBoundaryOrOnACellPlane) {
    // On the min face, going in; on the max face, going in; exactly on the plane x = 2.
    EXPECT_EQ(indices(walk(kFourCubed, {{0, 1.5f, 1.5f}, {1, 0, 0}})),
              (std::vector<std::uint32_t>{20, 21, 22, 23}));
    EXPECT_EQ(indices(walk(kFourCubed, {{4, 1.5f, 1.5f}, {-1, 0, 0}})),
              (std::vector<std::uint32_t>{23, 22, 21, 20}));
    EXPECT_EQ(indices(walk(kFourCubed, {{2, 1.5f, 1.5f}, {1, 0, 0}})),
              (std::vector<std::uint32_t>{22, 23}));
    // On the max face going out: the boundary cell only, for no length of ray.
    EXPECT_EQ(indices(walk(kFourCubed, {{4, 1.5f, 1.5f}, {1, 0, 0}})),
              (std::vector<std::uint32_t>{23}));
}

TEST(WalkGrid, MissingNanAndZeroDirections) {
    EXPECT_TRUE(walk(kFourCubed, {{-1, 5, 0}, {1, 0, 0}}).empty());   // passes above
    EXPECT_TRUE(walk(kFourCubed, {{-1, 1, 1}, {-1, 0, 0}}).empty());  // points away
    const float nan = std::numeric_limits<float>::quiet_NaN();
    EXPECT_TRUE(walk(kFourCubed, {{1, 1, 1}, {nan, 0, 1}}).empty());
    EXPECT_TRUE(walk(kFourCubed, {{nan, 1, 1}, {0, 0, 1}}).empty());
    // A zero direction stays in the origin's cell; from outside it reaches nothing.
    EXPECT_EQ(indices(walk(kFourCubed, {{1.5f, 2.5f, 3.5f}, {0, 0, 0}})),
              (std::vector<std::uint32_t>{(3 * 4 + 2) * 4 + 1}));
    EXPECT_TRUE(walk(kFourCubed, {{-1, 2, 2}, {0, 0, 0}}).empty());
}

TEST(WalkGrid, StopsWhenVisitSaysSo) {
    int calls = 0;
    walk_grid(kFourCubed, {{-1, 0.5f, 0.5f}, {1, 0, 0}}, {},
              [&](std::uint32_t, Interval) { return ++calls < 2; });
    EXPECT_EQ(calls, 2);
}

TEST(Mailbox, RemembersRecentIdsAndForgetsOnlyByEviction) {
    Mailbox m;
    EXPECT_TRUE(m.first_visit(7));
    EXPECT_FALSE(m.first_visit(7));
    EXPECT_TRUE(m.first_visit(7 + Mailbox::kSlots));  // same slot: evicts 7
    EXPECT_TRUE(m.first_visit(7));                    // tested again, never skipped wrongly
    EXPECT_TRUE(m.first_visit(0));
    EXPECT_FALSE(m.first_visit(0));
}

TEST(GridAggregate, FlatSceneGetsOneCellAcrossItsPlane) {
    std::vector<Primitive> prims;
    for (int i = 0; i < 20; ++i)
        for (int j = 0; j < 20; ++j)
            prims.push_back(
                {Triangle{{Point3{float(i), 0, float(j)}, Point3{float(i + 1), 0, float(j)},
                           Point3{float(i), 0, float(j + 1)}}}});
    const GridAggregate grid(prims);
    EXPECT_EQ(grid.layout().resolution[1], 1);
    // 400 primitives at 4 cells each on a square: about 40 x 40.
    EXPECT_NEAR(grid.layout().resolution[0], 40, 1);
    EXPECT_NEAR(grid.layout().resolution[2], 40, 1);
    const auto hit = grid.intersect({{3.25f, 5, 7.25f}, {0, -1, 0}}, {}, ~0u);
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->primitive, 3u * 20 + 7);
    EXPECT_FLOAT_EQ(hit->shape_hit.t, 5);
}

TEST(GridAggregate, CellsListOverlappingPrimitivesInIncreasingIndex) {
    // A long box across the whole scene is listed in every cell of its row.
    std::vector<Primitive> prims{{Box{{0, 0, 0}, {8, 1, 1}}}};
    for (int i = 0; i < 8; ++i) prims.push_back({Sphere{{float(i) + 0.5f, 4.5f, 0.5f}, 0.25f}});
    const GridAggregate grid(prims, {.density = 4});
    std::size_t cells_with_box = 0;
    for (std::uint32_t c = 0; c < grid.layout().cell_count(); ++c) {
        const auto list = grid.cell_primitives(c);
        EXPECT_TRUE(std::is_sorted(list.begin(), list.end()));
        cells_with_box += !list.empty() && list[0] == 0;
    }
    EXPECT_GE(cells_with_box, std::size_t(grid.layout().resolution[0]));
    // Along the box, from its far end: the nearest face, found once however many cells.
    const auto hit = grid.intersect({{10, 0.5f, 0.5f}, {-1, 0, 0}}, {}, ~0u);
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->primitive, 0u);
    EXPECT_FLOAT_EQ(hit->shape_hit.t, 2);
}

TEST(GridAggregate, HitBeyondItsCellIsBeatenByANearerOneInALaterCell) {
    // The slanted triangle overlaps every cell the ray crosses and is tested in the first one,
    // but the ray meets it only at z = 5 (t = 8); the small sphere at z = 3, in a cell between,
    // is nearer (t = 5.8) and must win. Small spheres off the ray give the grid its cells.
    std::vector<Primitive> prims{{Triangle{{Point3{-1, 1, 0}, Point3{1, 1, 0}, Point3{0, 0, 10}}}}};
    for (int i = 0; i < 64; ++i)
        prims.push_back(
            {Sphere{{i % 2 ? 1.5f : -1.5f, i / 2 % 2 ? 1.5f : -1.5f, 0.75f * float(i / 4)}, 0.1f}});
    prims.push_back({Sphere{{0, 0.5f, 3}, 0.2f}});
    const GridAggregate grid(prims);
    ASSERT_GT(grid.layout().resolution[2], 4);
    const Ray ray{{0, 0.5f, -3}, {0, 0, 1}};
    const auto hit = grid.intersect(ray, {}, ~0u);
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->primitive, 65u);
    EXPECT_NEAR(hit->shape_hit.t, 5.8f, 1e-5);
    EXPECT_FALSE(grid.occluded(ray, {0, 5.5f}, ~0u));
    EXPECT_TRUE(grid.occluded(ray, {0, 6}, ~0u));
}

TEST(GridAggregate, CoincidentPrimitivesFallBackToFewCellsWithinTheReferenceBudget) {
    const std::vector<Primitive> prims(50000, Primitive{Sphere{{1, 2, 3}, 1}});
    const GridAggregate grid(prims);
    EXPECT_LE(double(grid.reference_count()), 16.0 * 50000 + 4096);
    EXPECT_LT(grid.layout().cell_count(), 20u);
    const auto hit = grid.intersect({{1, 2, -5}, {0, 0, 1}}, {}, ~0u);
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->primitive, 0u);  // equal t everywhere: the lowest index
    EXPECT_FLOAT_EQ(hit->shape_hit.t, 7);
}

TEST(GridAggregate, MemoryIsCellsPlusReferences) {
    std::vector<Primitive> prims;
    for (int i = 0; i < 1000; ++i)
        prims.push_back({Sphere{{float(i % 10), float(i / 10 % 10), float(i / 100)}, 0.3f}});
    prims.push_back({Plane{}});
    const GridAggregate grid(prims);
    const std::size_t cells = grid.layout().cell_count();
    // Offsets and cell lists of 4 bytes, and the 8-byte references (one a primitive).
    const std::size_t listed = (cells + 1 + grid.reference_count() + 1) * 4 + 8 * prims.size();
    EXPECT_GE(grid.memory_bytes(), listed);
    EXPECT_LT(grid.memory_bytes(), listed + 1024);
    EXPECT_EQ(grid.bounds().min, (Point3{-0.3f, -0.3f, -0.3f}));  // planes left out
}

}  // namespace
}  // namespace glint
