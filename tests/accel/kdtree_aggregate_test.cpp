// The kd-tree: its 8-byte nodes, SAH splits that cut off empty space, bounded depth on
// coincident primitives, and front-to-back traversal that stops at the first leaf with a hit.
#include "glint/accel/kdtree_aggregate.h"

#include <gtest/gtest.h>

#include <vector>

namespace glint {
namespace {

TEST(KdNode, PacksAxisSplitChildAndLeafCounts) {
    KdNode interior = KdNode::interior(2, 1.5f);
    interior.set_above_child(12345);
    EXPECT_FALSE(interior.is_leaf());
    EXPECT_EQ(interior.axis(), 2);
    EXPECT_EQ(interior.split(), 1.5f);
    EXPECT_EQ(interior.above_child(), 12345u);

    const KdNode leaf = KdNode::leaf(7, 99);
    EXPECT_TRUE(leaf.is_leaf());
    EXPECT_EQ(leaf.primitive_count(), 7u);
    EXPECT_EQ(leaf.payload, 99u);
}

// Two clusters of small spheres far apart along x: the SAH puts the root's plane in the empty
// gap between them, so no primitive is listed on both sides.
TEST(KdTreeAggregate, RootSplitsTheEmptyGapBetweenTwoClusters) {
    std::vector<Primitive> prims;
    for (int i = 0; i < 20; ++i) {
        prims.push_back({Sphere{{float(i % 5) * 0.3f, float(i / 5) * 0.3f, 0}, 0.1f}});
        prims.push_back({Sphere{{100 + float(i % 5) * 0.3f, float(i / 5) * 0.3f, 0}, 0.1f}});
    }
    const KdTreeAggregate tree(prims);
    const KdNode& root = tree.nodes()[0];
    ASSERT_FALSE(root.is_leaf());
    EXPECT_EQ(root.axis(), 0);
    EXPECT_GT(root.split(), 1.3f);
    EXPECT_LT(root.split(), 99.9f);
    EXPECT_GE(tree.reference_count(), prims.size());
}

TEST(KdTreeAggregate, LeavesListTheirPrimitivesInIncreasingIndex) {
    std::vector<Primitive> prims;
    for (int i = 0; i < 300; ++i)
        prims.push_back({Sphere{{float(i % 10), float((i / 10) % 10), float(i / 100)}, 0.7f}});
    const KdTreeAggregate tree(prims);
    std::size_t references = 0;
    for (const KdNode& node : tree.nodes()) {
        if (!node.is_leaf()) continue;
        const auto list = tree.leaf_primitives(node);
        references += list.size();
        for (std::size_t k = 1; k < list.size(); ++k) EXPECT_LT(list[k - 1], list[k]);
    }
    EXPECT_EQ(references, tree.reference_count());
    EXPECT_LE(tree.depth(), kKdMaxDepth - 1);
}

// A million coincident primitives cannot be separated by any plane: the "bad refines" rule ends
// the recursion after a few levels, with all of them in one leaf, not kKdMaxDepth levels of
// copies.
TEST(KdTreeAggregate, CoincidentPrimitivesEndInOneShallowLeaf) {
    const std::vector<Primitive> prims(
        1000000, Primitive{Triangle{{Point3{0, 0, 0}, Point3{1, 0, 0}, Point3{0, 1, 0}}}});
    const KdTreeAggregate tree(prims);
    EXPECT_LE(tree.depth(), 4);
    EXPECT_LE(tree.reference_count(), 4 * prims.size());
    const auto hit = tree.intersect({{0.25f, 0.25f, -1}, {0, 0, 1}}, {}, ~0u);
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit->shape_hit.t, 1);
    EXPECT_EQ(hit->primitive, 0u);  // equal t: the lowest index
}

// A row of unit spheres along z: the ray along the row hits the first; the nearest hit is found
// in the first leaf and farther leaves are never needed for the answer.
TEST(KdTreeAggregate, ClosestHitAlongARowIsTheFirstSphere) {
    std::vector<Primitive> prims;
    for (int i = 0; i < 64; ++i) prims.push_back({Sphere{{0, 0, 3.0f * float(i)}, 1}});
    const KdTreeAggregate tree(prims);
    const auto hit = tree.intersect({{0, 0, -10}, {0, 0, 1}}, {}, ~0u);
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->primitive, 0u);
    EXPECT_FLOAT_EQ(hit->shape_hit.t, 9);
    // Backwards from beyond the row: the last sphere, at z = 189, front face at 190.
    const auto back = tree.intersect({{0, 0, 200}, {0, 0, -1}}, {}, ~0u);
    ASSERT_TRUE(back);
    EXPECT_EQ(back->primitive, 63u);
    EXPECT_FLOAT_EQ(back->shape_hit.t, 10);
    // A segment between spheres 3 and 4 (z in (10, 11)) hits nothing and is not occluded.
    EXPECT_FALSE(tree.intersect({{0, 0, 10.1f}, {0, 0, 1}}, {0, 0.8f}, ~0u));
    EXPECT_FALSE(tree.occluded({{0, 0, 10.1f}, {0, 0, 1}}, {0, 0.8f}, ~0u));
    EXPECT_TRUE(tree.occluded({{0, 0, 10.1f}, {0, 0, 1}}, {0, 2}, ~0u));
}

TEST(KdTreeAggregate, BoundsLeaveOutPlanesAndEmptyTreeHitsNothing) {
    const std::vector<Primitive> prims{{Plane{}}, {Sphere{{1, 2, 3}, 1}}};
    const KdTreeAggregate tree(prims);
    EXPECT_EQ(tree.bounds().min, (Point3{0, 1, 2}));
    EXPECT_EQ(tree.bounds().max, (Point3{2, 3, 4}));
    const std::vector<Primitive> none;
    const KdTreeAggregate empty(none);
    EXPECT_TRUE(empty.nodes().empty());
    EXPECT_FALSE(empty.intersect({{0, 0, 0}, {0, 0, 1}}, {}, ~0u));
}

TEST(KdTreeAggregate, MemoryIsNodesPlusLeafLists) {
    std::vector<Primitive> prims;
    for (int i = 0; i < 1000; ++i)
        prims.push_back({Sphere{{float(i % 10), float((i / 10) % 10), float(i / 100)}, 0.4f}});
    const KdTreeAggregate tree(prims);
    EXPECT_GE(tree.memory_bytes(), tree.nodes().size() * sizeof(KdNode));
    EXPECT_LT(tree.memory_bytes(), 200 * prims.size());
}

}  // namespace
}  // namespace glint
