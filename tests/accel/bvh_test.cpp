// The BVH: structure invariants of the build (degenerate inputs included) and traversal against
// brute force on random triangle soups.
#include "glint/accel/bvh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "common/under_sanitizer.h"
#include "glint/geometry/triangle.h"

namespace glint {
namespace {

// A million under a sanitizer takes minutes (ThreadSanitizer: 284 s); 100,000 still makes the
// deep recursion an unsplittable pile would cause.
constexpr std::size_t kCoincidentCount = testing::kUnderSanitizer ? 100'000 : 1'000'000;

// Every primitive appears in exactly one leaf, leaves hold at most max_leaf_size, each node's
// box contains its children's and its primitives', and depth stays below kBvhMaxDepth.
void expect_valid(const Bvh& bvh, const std::vector<Bounds3>& bounds, int max_leaf = 4) {
    ASSERT_EQ(bvh.primitive_indices.size(), bounds.size());
    std::vector<int> seen(bounds.size(), 0);
    struct Item {
        std::uint32_t node;
        int depth;
    };
    std::vector<Item> stack{{0, 0}};
    std::size_t visited = 0;
    const auto inside = [](const Bounds3& inner, const Bounds3& outer) {
        return inner.is_empty() || (outer.contains(inner.min) && outer.contains(inner.max));
    };
    while (!stack.empty()) {
        const Item item = stack.back();
        stack.pop_back();
        ++visited;
        ASSERT_LT(item.depth, kBvhMaxDepth);
        const BvhNode& node = bvh.nodes[item.node];
        if (node.is_leaf()) {
            ASSERT_LE(int(node.count), max_leaf);
            for (std::uint32_t i = 0; i < node.count; ++i) {
                const std::uint32_t p = bvh.primitive_indices[node.offset + i];
                ++seen[p];
                ASSERT_TRUE(inside(bounds[p], node.bounds));
            }
        } else {
            const std::uint32_t a = item.node + 1, b = node.offset;
            ASSERT_LT(b, bvh.nodes.size());
            ASSERT_TRUE(inside(bvh.nodes[a].bounds, node.bounds));
            ASSERT_TRUE(inside(bvh.nodes[b].bounds, node.bounds));
            stack.push_back({a, item.depth + 1});
            stack.push_back({b, item.depth + 1});
        }
    }
    EXPECT_EQ(visited, bvh.nodes.size());
    for (std::size_t i = 0; i < seen.size(); ++i) ASSERT_EQ(seen[i], 1) << "primitive " << i;
}

std::vector<Triangle> random_soup(int count, unsigned seed, float spread = 10, float size = 1) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-1, 1);
    std::vector<Triangle> soup;
    for (int i = 0; i < count; ++i) {
        const Point3 c{u(rng) * spread, u(rng) * spread, u(rng) * spread};
        Triangle t;
        for (auto& v : t.vertices) v = c + Vector3{u(rng), u(rng), u(rng)} * size;
        soup.push_back(t);
    }
    return soup;
}

std::vector<Bounds3> bounds_of(const std::vector<Triangle>& soup) {
    std::vector<Bounds3> b;
    for (const Triangle& t : soup) b.push_back(t.bounds());
    return b;
}

std::optional<ShapeHit> brute_force(const std::vector<Triangle>& soup, const Ray& ray,
                                    Interval range) {
    std::optional<ShapeHit> nearest;
    for (std::uint32_t i = 0; i < soup.size(); ++i) {
        if (auto hit = soup[i].intersect(ray, range)) {
            hit->part = i;
            range.max = hit->t;
            nearest = hit;
        }
    }
    return nearest;
}

std::optional<ShapeHit> with_bvh(const Bvh& bvh, const std::vector<Triangle>& soup, const Ray& ray,
                                 Interval range) {
    ShapeHit nearest;
    const auto t =
        bvh_closest_hit(bvh, ray, range, [&](std::uint32_t i, Interval r) -> std::optional<float> {
            auto hit = soup[i].intersect(ray, r);
            if (!hit) return std::nullopt;
            nearest = *hit;
            nearest.part = i;
            return hit->t;
        });
    if (!t) return std::nullopt;
    return nearest;
}

TEST(Bvh, NoPrimitivesGivesAnEmptyTreeThatNothingHits) {
    const Bvh bvh = build_bvh({});
    EXPECT_TRUE(bvh.nodes.empty());
    EXPECT_TRUE(bvh.bounds().is_empty());
    const Ray ray{{0, 0, 0}, {0, 0, 1}};
    EXPECT_FALSE(bvh_closest_hit(bvh, ray, {},
                                 [](std::uint32_t, Interval) { return std::optional<float>(1); }));
    EXPECT_FALSE(bvh_any_hit(bvh, ray, {}, [](std::uint32_t, Interval) { return true; }));
}

TEST(Bvh, OnePrimitiveIsOneLeaf) {
    const std::vector<Bounds3> b{{{0, 0, 0}, {1, 1, 1}}};
    const Bvh bvh = build_bvh(b);
    ASSERT_EQ(bvh.nodes.size(), 1u);
    EXPECT_TRUE(bvh.nodes[0].is_leaf());
    EXPECT_EQ(bvh.nodes[0].count, 1);
    expect_valid(bvh, b);
}

TEST(Bvh, NodesAre32Bytes) { EXPECT_EQ(sizeof(BvhNode), 32u); }

TEST(Bvh, TwoSeparateBoxesAreSplitAlongTheirAxis) {
    const std::vector<Bounds3> b{{{0, 0, 0}, {1, 1, 1}}, {{10, 0, 0}, {11, 1, 1}}};
    BvhBuildOptions options;
    options.max_leaf_size = 1;
    const Bvh bvh = build_bvh(b, options);
    ASSERT_EQ(bvh.nodes.size(), 3u);
    EXPECT_EQ(bvh.nodes[0].axis, 0);
    EXPECT_EQ(bvh.nodes[0].bounds.min, (Point3{0, 0, 0}));
    EXPECT_EQ(bvh.nodes[0].bounds.max, (Point3{11, 1, 1}));
    expect_valid(bvh, b, 1);
}

// Two rows of boxes, 4 apart in y and spread over 12 in x: the longest centroid axis is x, but
// the split that SAH prefers separates the rows, along y. The binning tries every axis.
TEST(Bvh, SplitsAlongTheCheapestAxisNotJustTheLongest) {
    std::vector<Bounds3> b;
    for (int row = 0; row < 2; ++row)
        for (int i = 0; i < 4; ++i) {
            const float x = 4.0f * float(i), y = 4.0f * float(row);
            b.push_back({{x, y, 0}, {x + 1, y + 1, 1}});
        }
    BvhBuildOptions options;
    options.max_leaf_size = 4;
    const Bvh bvh = build_bvh(b, options);
    expect_valid(bvh, b);
    ASSERT_GT(bvh.nodes.size(), 1u);
    EXPECT_EQ(bvh.nodes[0].axis, 1);
    const BvhNode& first = bvh.nodes[1];
    const BvhNode& second = bvh.nodes[bvh.nodes[0].offset];
    EXPECT_EQ(first.bounds.max.y, 1.0f);   // the row at y = 0 ...
    EXPECT_EQ(second.bounds.min.y, 4.0f);  // ... and the row at y = 4
}

// A jack: three thin bars crossing at one point. Their centroids coincide, so no centroid plane
// separates them; binned by their boxes' lower corners they still go to leaves of their own
// (one leaf of all three would be tested by every ray through their common box).
TEST(Bvh, ShapesWithOneCentroidButDifferentBoxesAreSeparated) {
    const std::vector<Bounds3> b{{{-1, -0.1f, -0.1f}, {1, 0.1f, 0.1f}},
                                 {{-0.1f, -1, -0.1f}, {0.1f, 1, 0.1f}},
                                 {{-0.1f, -0.1f, -1}, {0.1f, 0.1f, 1}}};
    const Bvh bvh = build_bvh(b);
    expect_valid(bvh, b);
    for (const BvhNode& n : bvh.nodes) {
        if (n.is_leaf()) {
            EXPECT_EQ(n.count, 1);
        }
    }
}

TEST(Bvh, AMillionCoincidentPrimitivesTerminateWithSmallLeaves) {
    const std::vector<Bounds3> b(kCoincidentCount, Bounds3{{1, 2, 3}, {1, 2, 3}});  // no extent
    const Bvh bvh = build_bvh(b);
    expect_valid(bvh, b);
}

TEST(Bvh, EqualCentroidsWithDifferentSizesAndZeroExtentBoxes) {
    std::vector<Bounds3> b;
    for (int i = 0; i < 1000; ++i) {
        const float r = float(i % 7);
        b.push_back({{-r, -r, -r}, {r, r, r}});
    }
    for (int i = 0; i < 100; ++i) b.push_back({{float(i), 0, 0}, {float(i), 0, 0}});
    expect_valid(build_bvh(b), b);
}

TEST(Bvh, NonFiniteBoundsDoNotBreakTheBuild) {
    std::vector<Bounds3> b = bounds_of(random_soup(200, 3));
    b[5] = Bounds3{};  // empty: inverted infinities
    b[9] = {{-kInfinity, 0, 0}, {kInfinity, 1, 1}};
    b[11].min.x = std::numeric_limits<float>::quiet_NaN();
    const Bvh bvh = build_bvh(b);
    EXPECT_EQ(bvh.primitive_indices.size(), b.size());
    std::vector<std::uint32_t> sorted(bvh.primitive_indices.begin(), bvh.primitive_indices.end());
    std::sort(sorted.begin(), sorted.end());
    for (std::uint32_t i = 0; i < sorted.size(); ++i) ASSERT_EQ(sorted[i], i);
}

TEST(Bvh, SkewedInputStaysWithinTheDepthBound) {
    // Exponentially spaced boxes make SAH cut off one primitive at a time.
    std::vector<Bounds3> b;
    for (int i = 0; i < 120; ++i) {
        const float x = std::ldexp(1.0f, i);
        b.push_back({{x, 0, 0}, {x * 1.01f, 1, 1}});
    }
    BvhBuildOptions options;
    options.max_leaf_size = 1;
    expect_valid(build_bvh(b, options), b, 1);
}

TEST(Bvh, LeafSizeOptionIsRespected) {
    const std::vector<Bounds3> b = bounds_of(random_soup(3000, 1));
    for (int leaf : {1, 2, 8}) {
        BvhBuildOptions options;
        options.max_leaf_size = leaf;
        expect_valid(build_bvh(b, options), b, leaf);
    }
}

// Coincident boxes, which no split parts: leaves are cut by count at max_leaf_size tests, a test
// being one shape of kind 0 or a block of four of another kind, so sixteen triangles (four blocks)
// or four shapes.
TEST(Bvh, LeavesHoldAtMostMaxLeafTestsOfShapesOrBlocks) {
    const std::vector<Bounds3> b(128, Bounds3{{0, 0, 0}, {1, 1, 1}});
    BvhBuildOptions options;
    options.max_leaf_size = 4;
    options.block_size = 4;
    for (const std::uint8_t kind : {0, 1}) {
        const std::vector<std::uint8_t> kinds(b.size(), kind);
        const Bvh bvh = build_bvh(b, options, kinds);
        const std::uint32_t most = kind == 0 ? 4 : 16;
        expect_valid(bvh, b, int(most));
        for (const BvhNode& n : bvh.nodes) {
            if (n.is_leaf()) {
                EXPECT_EQ(n.count, most) << int(kind);
            }
        }
    }
}

TEST(Bvh, ClosestHitMatchesBruteForceOnRandomRays) {
    for (unsigned seed : {1u, 2u, 3u}) {
        const auto soup = random_soup(2000, seed);
        const Bvh bvh = build_bvh(bounds_of(soup));
        std::mt19937 rng(seed + 100);
        std::uniform_real_distribution<float> u(-1, 1);
        int hits = 0;
        for (int i = 0; i < 3000; ++i) {
            // Origins inside and outside the soup; every 4th ray runs along an axis.
            const Point3 o{u(rng) * 15, u(rng) * 15, u(rng) * 15};
            Vector3 d{u(rng), u(rng), u(rng)};
            if (i % 4 == 0)
                d = i % 3 == 0   ? Vector3{1, 0, 0}
                    : i % 3 == 1 ? Vector3{0, -1, 0}
                                 : Vector3{0, 0, 1};
            if (length(d) < 1e-3f) continue;
            const Ray ray{o, normalize(d)};
            const Interval range{0, i % 5 == 0 ? 8.0f : kInfinity};
            const auto expected = brute_force(soup, ray, range);
            const auto got = with_bvh(bvh, soup, ray, range);
            ASSERT_EQ(bool(expected), bool(got)) << "seed " << seed << " ray " << i;
            if (!expected) continue;
            ++hits;
            ASSERT_EQ(got->t, expected->t) << "seed " << seed << " ray " << i;
            const bool any = bvh_any_hit(bvh, ray, range, [&](std::uint32_t k, Interval r) {
                return soup[k].intersect(ray, r).has_value();
            });
            ASSERT_TRUE(any);
        }
        EXPECT_GT(hits, 500);
    }
}

TEST(Bvh, RaysStartingOnFacesAndAlongAxisAlignedFacesMatchBruteForce) {
    // Axis-aligned triangles on a grid: their boxes are flat, and rays start exactly on them or
    // run exactly in their planes.
    std::vector<Triangle> soup;
    for (int i = 0; i < 10; ++i) {
        for (int j = 0; j < 10; ++j) {
            const float x = float(i), y = float(j);
            soup.push_back({{Point3{x, y, 0}, Point3{x + 1, y, 0}, Point3{x, y + 1, 0}}});
            soup.push_back({{Point3{x, 0, y}, Point3{x + 1, 0, y}, Point3{x, 0, y + 1}}});
            soup.push_back({{Point3{0, x, y}, Point3{0, x + 1, y}, Point3{0, x, y + 1}}});
        }
    }
    const Bvh bvh = build_bvh(bounds_of(soup));
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(0, 10);
    std::uniform_int_distribution<int> axis(0, 5);
    for (int i = 0; i < 5000; ++i) {
        // Starts on a face (z = 0, y = 0 or x = 0) or in a face's plane, axis-parallel or not.
        Point3 o{u(rng), u(rng), u(rng)};
        const int face = i % 3;
        if (face == 0) o.z = 0;
        if (face == 1) o.y = 0;
        if (face == 2) o.x = 0;
        const int a = axis(rng);
        Vector3 d = a == 0   ? Vector3{1, 0, 0}
                    : a == 1 ? Vector3{0, 1, 0}
                    : a == 2 ? Vector3{0, 0, 1}
                    : a == 3 ? -Vector3{1, 0, 0}
                    : a == 4 ? -Vector3{0, 1, 0}
                             : -Vector3{0, 0, 1};
        if (i % 2 == 0) d = normalize(Vector3{u(rng) - 5, u(rng) - 5, u(rng) - 5});
        const Ray ray{o, d};
        const auto expected = brute_force(soup, ray, {});
        const auto got = with_bvh(bvh, soup, ray, {});
        ASSERT_EQ(bool(expected), bool(got)) << "ray " << i;
        if (expected) {
            ASSERT_EQ(got->t, expected->t) << "ray " << i;
        }
    }
}

TEST(Bvh, AnyHitStopsAtTheFirstHit) {
    const auto soup = random_soup(500, 4, 1);  // dense: a ray through the middle hits many
    const Bvh bvh = build_bvh(bounds_of(soup));
    int calls = 0, hits = 0;
    const bool any =
        bvh_any_hit(bvh, Ray{{-20, 0.1f, 0.2f}, {1, 0, 0}}, {}, [&](std::uint32_t k, Interval r) {
            ++calls;
            const bool hit = soup[k].intersect(Ray{{-20, 0.1f, 0.2f}, {1, 0, 0}}, r).has_value();
            hits += hit;
            return hit;
        });
    EXPECT_TRUE(any);
    EXPECT_EQ(hits, 1);
    EXPECT_LT(calls, 500);
}

TEST(Bvh, SlabTestWorkedExample) {
    const Bounds3 box{{1, 1, 1}, {2, 2, 2}};
    // From the origin along (1,1,1)/sqrt(3): enters at t = sqrt(3), leaves at 2 sqrt(3).
    const BvhRay r(Ray{{0, 0, 0}, normalize(Vector3{1, 1, 1})});
    EXPECT_TRUE(slab_hit(box, r, 0, kInfinity));
    EXPECT_TRUE(slab_hit(box, r, 0, 1.7321f));
    EXPECT_FALSE(slab_hit(box, r, 0, 1.73f));
    EXPECT_FALSE(slab_hit(box, r, 3.47f, kInfinity));
    // Parallel to x on the box's face plane y = 1: boundaries count as inside.
    const BvhRay on_face(Ray{{0, 1, 1.5f}, {1, 0, 0}});
    EXPECT_TRUE(slab_hit(box, on_face, 0, kInfinity));
    const BvhRay beside(Ray{{0, 0.99f, 1.5f}, {1, 0, 0}});
    EXPECT_FALSE(slab_hit(box, beside, 0, kInfinity));
    // Negative zero components (as -Vector3{1, 0, 0} has) are parallel too, not a miss.
    const BvhRay negated(Ray{{3, 1.5f, 1.5f}, -Vector3{1, 0, 0}});
    EXPECT_TRUE(slab_hit(box, negated, 0, kInfinity));
    const BvhRay negated_on_face(Ray{{3, 1, 2}, -Vector3{1, 0, 0}});
    EXPECT_TRUE(slab_hit(box, negated_on_face, 0, kInfinity));
}

}  // namespace
}  // namespace glint
