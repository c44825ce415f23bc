// The statistics of every acceleration structure, checked against counts made by hand: the SAH
// sum on a tiny worked case, and on built structures the references their leaves hold, the node
// counts and the depth.
#include "glint/accel/accel_stats.h"

#include <gtest/gtest.h>

#include <vector>

#include "glint/accel/bvh_aggregate.h"
#include "glint/accel/grid_aggregate.h"
#include "glint/accel/kdtree_aggregate.h"
#include "glint/accel/make_aggregate.h"
#include "glint/accel/primitive_list.h"

namespace glint {
namespace {

const Bounds3 kUnitCube{{0, 0, 0}, {1, 1, 1}};  // surface area 6

// A root over two halves of the unit cube, split at x = 0.5: each half has area
// 2 (0.5 + 1 + 0.5) = 4, a chance of 4/6 = 2/3 to be entered by a ray entering the root.
TEST(AccelStatsTally, WorkedSahOfARootAndTwoLeaves) {
    AccelStatsTally tally(kUnitCube);
    tally.interior(kUnitCube);                                 // 1 x 1 (always entered)
    tally.leaf({{0, 0, 0}, {0.5f, 1, 1}}, 1, 2);               // 2 tests x 2/3 = 4/3
    tally.leaf({{0.5f, 0, 0}, {1, 1, 1}}, 1, 1);               // 1 test x 2/3 = 2/3
    const AccelStats s = tally.finish(1, 100);                 // one plane: 1 test for every ray
    EXPECT_NEAR(s.sah_cost, 1 + 4.0 / 3 + 2.0 / 3 + 1, 1e-9);  // = 4
    EXPECT_EQ(s.interior_nodes, 1u);
    EXPECT_EQ(s.leaves, 2u);
    EXPECT_EQ(s.empty_leaves, 0u);
    EXPECT_EQ(s.references, 3u);
    EXPECT_EQ(s.min_leaf_size, 1u);
    EXPECT_EQ(s.max_leaf_size, 2u);
    EXPECT_DOUBLE_EQ(s.mean_leaf_size, 1.5);
    EXPECT_EQ(s.max_depth, 1);
    EXPECT_DOUBLE_EQ(s.mean_leaf_depth, 1.0);
    EXPECT_EQ(s.unbounded, 1u);
    EXPECT_EQ(s.memory_bytes, 100u);
}

// Two cells of the unit cube: each is entered with chance 2/3 and costs a step, plus its tests.
TEST(AccelStatsTally, GridCellsCostAStepEachAndEmptyCellsCountApart) {
    AccelStatsTally tally(kUnitCube);
    tally.cell({{0, 0, 0}, {0.5f, 1, 1}}, 2);  // (1 + 2) x 2/3 = 2
    tally.cell({{0.5f, 0, 0}, {1, 1, 1}}, 0);  // (1 + 0) x 2/3 = 2/3
    const AccelStats s = tally.finish(0, 0);
    EXPECT_NEAR(s.sah_cost, 8.0 / 3, 1e-9);
    EXPECT_EQ(s.interior_nodes, 0u);
    EXPECT_EQ(s.leaves, 2u);
    EXPECT_EQ(s.empty_leaves, 1u);
    EXPECT_EQ(s.min_leaf_size, 2u);
    EXPECT_EQ(s.max_leaf_size, 2u);
    EXPECT_DOUBLE_EQ(s.mean_leaf_size, 2.0);  // over the occupied cells
    EXPECT_EQ(s.max_depth, 0);
}

TEST(AccelStatsTally, ARootOfZeroAreaCountsEveryNodeAsEntered) {
    const Bounds3 point{{1, 1, 1}, {1, 1, 1}};
    AccelStatsTally tally(point);
    tally.leaf(point, 0, 3);
    EXPECT_DOUBLE_EQ(tally.finish(0, 0).sah_cost, 3.0);
}

// A closed cube of 12 triangles, [lo, lo + 1]^3.
Shape cube_mesh(Point3 lo) {
    MeshData arrays;
    for (int k = 0; k < 8; ++k)
        arrays.positions.push_back(
            {lo.x + float(k & 1), lo.y + float((k >> 1) & 1), lo.z + float((k >> 2) & 1)});
    const std::uint32_t faces[6][4] = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1},
                                       {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
    for (const auto& f : faces) {
        arrays.triangles.push_back({f[0], f[1], f[2]});
        arrays.triangles.push_back({f[0], f[2], f[3]});
    }
    MeshBuild built = build_mesh(std::move(arrays));
    EXPECT_TRUE(built.mesh) << built.error;
    return TriangleMesh{built.mesh};
}

// 40 spheres in a row, two boxes, a 12-triangle mesh and a plane: 55 references, 54 bounded.
std::vector<Primitive> small_scene() {
    std::vector<Primitive> prims;
    for (int i = 0; i < 40; ++i)
        prims.push_back({Sphere{{float(i % 8) * 1.5f, float(i / 8) * 1.5f, 0}, 0.5f}});
    prims.push_back({Box{{20, 0, 0}, {21, 1, 1}}});
    prims.push_back({Box{{-5, -5, -5}, {-4, 6, -4}}});
    prims.push_back({cube_mesh({3, 3, 5})});
    prims.push_back({Plane{{0, -1, 0}, {0, 1, 0}}});
    return prims;
}
constexpr std::size_t kBoundedReferences = 40 + 2 + 12;

// What every structure's figures must satisfy, whatever its shape.
void expect_consistent(const AccelStats& s, const Aggregate& aggregate) {
    EXPECT_TRUE(s.available);
    EXPECT_EQ(s.unbounded, 1u);
    EXPECT_EQ(s.memory_bytes, aggregate.memory_bytes());
    const std::size_t filled = s.leaves - s.empty_leaves;
    ASSERT_GT(filled, 0u);
    EXPECT_NEAR(s.mean_leaf_size * double(filled), double(s.references), 1e-6);
    EXPECT_LE(s.min_leaf_size, s.max_leaf_size);
    EXPECT_LE(s.mean_leaf_depth, double(s.max_depth));
    // Every ray tests the plane; the root is entered; no more than every reference per leaf.
    EXPECT_GE(s.sah_cost, kSahIntersectionCost * 1);
    EXPECT_TRUE(std::isfinite(s.sah_cost));
}

TEST(AccelStats, ListIsOneLeafOfEveryBoundedReference) {
    const std::vector<Primitive> prims = small_scene();
    const PrimitiveList list(prims);
    const AccelStats s = list.statistics();
    expect_consistent(s, list);
    EXPECT_EQ(s.interior_nodes, 0u);
    EXPECT_EQ(s.leaves, 1u);
    EXPECT_EQ(s.references, kBoundedReferences);
    EXPECT_EQ(s.max_depth, 0);
    // The list tests everything: 54 + the plane.
    EXPECT_DOUBLE_EQ(s.sah_cost, double(kBoundedReferences + 1));
}

TEST(AccelStats, BvhLeavesHoldEachReferenceOnce) {
    const std::vector<Primitive> prims = small_scene();
    const BvhAggregate bvh(prims);
    const AccelStats s = bvh.statistics();
    expect_consistent(s, bvh);
    EXPECT_EQ(s.references, kBoundedReferences);
    EXPECT_EQ(s.empty_leaves, 0u);
    EXPECT_LE(s.max_leaf_size, 16u);  // kWideBvhTriangleBuildOptions: four blocks of four
    EXPECT_GE(s.interior_nodes, 1u);
    // Each interior node but the root, and each leaf, fills a slot of an interior node.
    EXPECT_LE(s.interior_nodes - 1 + s.leaves, s.interior_nodes * std::size_t(kWideBvhWidth));
    // Cheaper than testing everything, dearer than one test and the plane.
    EXPECT_LT(s.sah_cost, double(kBoundedReferences + 1));
}

TEST(AccelStats, KdTreeMatchesABruteForceWalkOfItsNodes) {
    const std::vector<Primitive> prims = small_scene();
    const KdTreeAggregate kd(prims);
    const AccelStats s = kd.statistics();
    expect_consistent(s, kd);
    std::size_t leaves = 0, empty = 0, held = 0;
    for (const KdNode& node : kd.nodes()) {
        if (!node.is_leaf()) continue;
        ++leaves;
        empty += node.primitive_count() == 0;
        held += kd.leaf_primitives(node).size();
    }
    EXPECT_EQ(s.leaves, leaves);
    EXPECT_EQ(s.interior_nodes, kd.nodes().size() - leaves);
    EXPECT_EQ(s.leaves, s.interior_nodes + 1);  // a binary tree
    EXPECT_EQ(s.empty_leaves, empty);
    EXPECT_EQ(s.references, held);
    EXPECT_EQ(s.references, kd.reference_count());
    EXPECT_GE(s.references, kBoundedReferences);  // straddlers are listed on both sides
    EXPECT_EQ(s.max_depth, kd.depth());
}

// The kd-tree's SAH recomputed from its nodes, each box cut from its parent's at the split.
double kd_sah(const KdTreeAggregate& kd, std::uint32_t index, const Bounds3& box,
              double root_area) {
    const KdNode& node = kd.nodes()[index];
    const double chance = double(box.surface_area()) / root_area;
    if (node.is_leaf()) return kSahIntersectionCost * node.primitive_count() * chance;
    Bounds3 below = box, above = box;
    (node.axis() == 0 ? below.max.x : node.axis() == 1 ? below.max.y : below.max.z) = node.split();
    (node.axis() == 0 ? above.min.x : node.axis() == 1 ? above.min.y : above.min.z) = node.split();
    return kSahTraversalCost * chance + kd_sah(kd, index + 1, below, root_area) +
           kd_sah(kd, node.above_child(), above, root_area);
}

TEST(AccelStats, KdTreeSahIsTheAreaWeightedSumOfItsNodes) {
    const std::vector<Primitive> prims = small_scene();
    const KdTreeAggregate kd(prims);
    // bounds() is the tree's root box before the few-ulp growth the tree adds.
    const Bounds3 root = kd.bounds();
    const double expected = kd_sah(kd, 0, root, root.surface_area()) + kSahIntersectionCost;
    EXPECT_NEAR(kd.statistics().sah_cost, expected, 1e-3 * expected);
}

TEST(AccelStats, GridCellsMatchItsCellLists) {
    const std::vector<Primitive> prims = small_scene();
    const GridAggregate grid(prims);
    const AccelStats s = grid.statistics();
    expect_consistent(s, grid);
    const GridLayout& layout = grid.layout();
    std::size_t empty = 0, held = 0;
    for (std::uint32_t c = 0; c < layout.cell_count(); ++c) {
        empty += grid.cell_primitives(c).empty();
        held += grid.cell_primitives(c).size();
    }
    EXPECT_EQ(s.interior_nodes, 0u);
    EXPECT_EQ(s.leaves, layout.cell_count());
    EXPECT_EQ(s.empty_leaves, empty);
    EXPECT_EQ(s.references, held);
    EXPECT_EQ(s.references, grid.reference_count());
    EXPECT_EQ(s.max_depth, 0);
}

TEST(AccelStats, EveryStructureOfAnEmptySceneHasNoLeaves) {
    const std::vector<Primitive> none;
    for (const std::string_view name : accel_names()) {
        const auto aggregate = make_aggregate(*accel_from_name(name), none);
        const AccelStats s = aggregate->statistics();
        EXPECT_EQ(s.references, 0u) << name;
        EXPECT_EQ(s.unbounded, 0u) << name;
        EXPECT_EQ(s.min_leaf_size, 0u) << name;
        EXPECT_EQ(s.sah_cost, 0.0) << name;
    }
}

}  // namespace
}  // namespace glint
