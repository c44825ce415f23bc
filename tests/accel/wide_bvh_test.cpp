// The wide BVH: collapse invariants, a build that is the same for any thread count, node tests
// that agree bit for bit across SIMD paths, and traversal against brute force on random and
// adversarial rays on every path.
#include "glint/accel/wide_bvh.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <optional>
#include <random>
#include <vector>

#include "common/under_sanitizer.h"
#include "glint/accel/wide_bvh_traversal.h"
#include "glint/geometry/simd_path.h"

namespace glint::wide_bvh_test {
namespace {

// A million under a sanitizer takes minutes (ThreadSanitizer: 284 s); 100,000 still makes the
// deep recursion an unsplittable pile would cause.
constexpr std::size_t kCoincidentCount = testing::kUnderSanitizer ? 100'000 : 1'000'000;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

std::vector<SimdPath> supported_paths() {
    std::vector<SimdPath> paths;
    for (const SimdPath p : kSimdPaths)
        if (simd_path_supported(p)) paths.push_back(p);
    return paths;
}

// Runs f on each supported path in turn, and restores the path in use after.
class EveryPath {
public:
    EveryPath() : saved_(simd_path()) {}
    ~EveryPath() { set_simd_path(saved_); }

    template <typename F>
    void run(F&& f) {
        for (const SimdPath p : supported_paths()) {
            ASSERT_TRUE(set_simd_path(p));
            f(p);
        }
    }

private:
    SimdPath saved_;
};

template <typename F>
void on_threads(int threads, F&& f) {
    tbb::global_control allow(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
    tbb::task_arena arena(threads);
    arena.execute(f);
}

// The test primitive: a box, hit where slab_hit's arithmetic (without the widening) says the ray
// enters it. Any box that contains it passes the BVH's (widened) node test whenever it is hit, so
// a correct traversal must report exactly the brute-force answer, ties included.
std::optional<float> box_hit(const Bounds3& b, const Ray& ray, Interval range) {
    const BvhRay r(ray);
    float lo = range.min, hi = range.max;
    for (int axis = 0; axis < 3; ++axis) {
        const float near = r.negative[axis] ? b.max[axis] : b.min[axis];
        const float far = r.negative[axis] ? b.min[axis] : b.max[axis];
        const float n = (near - r.origin[axis]) * r.inv_direction[axis];
        const float f = (far - r.origin[axis]) * r.inv_direction[axis];
        lo = n > lo ? n : lo;
        hi = f < hi ? f : hi;
    }
    if (!(lo <= hi)) return std::nullopt;
    return lo;
}

struct Nearest {
    float t = kInfinity;
    std::uint32_t index = 0;
    bool hit = false;
};

// Smaller t, then lower index: the order every aggregate follows.
void offer(Nearest& n, float t, std::uint32_t index) {
    if (!n.hit || t < n.t || (t == n.t && index < n.index)) n = {t, index, true};
}

Nearest brute_force(const std::vector<Bounds3>& boxes, const Ray& ray, Interval range) {
    Nearest n;
    for (std::uint32_t i = 0; i < boxes.size(); ++i) {
        if (const auto t = box_hit(boxes[i], ray, range)) {
            offer(n, *t, i);
            range.max = n.t;
        }
    }
    return n;
}

// The nearest box through the wide BVH, and the primitives in the order visited.
Nearest with_wide_bvh(const WideBvh& bvh, const std::vector<Bounds3>& boxes, const Ray& ray,
                      Interval range, std::vector<std::uint32_t>* visited = nullptr) {
    Nearest n;
    bvh_closest_hit(bvh, ray, range, [&](std::uint32_t i, Interval r) -> std::optional<float> {
        if (visited) visited->push_back(i);
        const auto t = box_hit(boxes[i], ray, r);
        if (!t) return std::nullopt;
        offer(n, *t, i);
        return n.t;
    });
    return n;
}

bool any_with_wide_bvh(const WideBvh& bvh, const std::vector<Bounds3>& boxes, const Ray& ray,
                       Interval range) {
    return bvh_any_hit(bvh, ray, range, [&](std::uint32_t i, Interval r) {
        return box_hit(boxes[i], ray, r).has_value();
    });
}

std::vector<Bounds3> random_boxes(int count, unsigned seed, float spread = 10, float size = 1) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-1, 1), unit(0, 1);
    std::vector<Bounds3> boxes;
    for (int i = 0; i < count; ++i) {
        const Point3 c{u(rng) * spread, u(rng) * spread, u(rng) * spread};
        const Vector3 h{unit(rng) * size, unit(rng) * size, unit(rng) * size};
        boxes.push_back({c - h, c + h});
    }
    return boxes;
}

// Unit cubes on an integer grid, some flattened to a face: shared faces, edges and corners.
std::vector<Bounds3> box_grid(int n) {
    std::vector<Bounds3> boxes;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            for (int k = 0; k < n; ++k) {
                const Point3 a{float(i), float(j), float(k)};
                Point3 b = a + Vector3{1, 1, 1};
                if ((i + j + k) % 5 == 0) b.y = a.y;  // flat
                boxes.push_back({a, b});
            }
    return boxes;
}

// Every primitive in exactly one leaf of at most max_leaf, each child box inside the box its
// parent's slot gives it, unused slots empty and last, every node reachable once, and depth
// below kBvhMaxDepth.
void expect_valid(const WideBvh& bvh, const std::vector<Bounds3>& bounds,
                  int max_leaf = kWideBvhBuildOptions.max_leaf_size) {
    ASSERT_EQ(bvh.primitive_indices.size(), bounds.size());
    if (bounds.empty()) {
        EXPECT_TRUE(bvh.nodes.empty());
        return;
    }
    std::vector<int> seen(bounds.size(), 0);
    const auto inside = [](const Bounds3& inner, const Bounds3& outer) {
        return inner.is_empty() || (outer.contains(inner.min) && outer.contains(inner.max));
    };
    struct Item {
        std::uint32_t node;
        Bounds3 box;
        int depth;
    };
    std::vector<Item> stack{{0, bvh.root_bounds, 0}};
    std::size_t visited = 0;
    while (!stack.empty()) {
        const Item item = stack.back();
        stack.pop_back();
        ++visited;
        ASSERT_LT(item.depth, kBvhMaxDepth);
        ASSERT_LT(item.node, bvh.nodes.size());
        const WideBvhNode& node = bvh.nodes[item.node];
        bool unused_seen = false;
        int used = 0;
        for (int k = 0; k < kWideBvhWidth; ++k) {
            const Bounds3 box = node.child_bounds(k);
            if (node.is_leaf(k) && node.count[k] == 0) {
                unused_seen = true;
                EXPECT_EQ(box.min.x, kInfinity);
                EXPECT_EQ(box.max.x, -kInfinity);
                continue;
            }
            ASSERT_FALSE(unused_seen) << "a used slot after an unused one";
            ++used;
            ASSERT_TRUE(inside(box, item.box));
            if (node.is_leaf(k)) {
                ASSERT_LE(int(node.count[k]), max_leaf);
                const std::uint32_t first = node.child[k] & ~kWideLeaf;
                for (std::uint32_t i = 0; i < node.count[k]; ++i) {
                    const std::uint32_t p = bvh.primitive_indices[first + i];
                    ++seen[p];
                    ASSERT_TRUE(inside(bounds[p], box)) << "primitive " << p;
                }
            } else {
                stack.push_back({node.child[k], box, item.depth + 1});
            }
        }
        // Only the root may have a single child (a tree that is one leaf).
        if (item.node != 0) {
            EXPECT_GE(used, 2);
        }
    }
    EXPECT_EQ(visited, bvh.nodes.size());
    for (std::size_t i = 0; i < seen.size(); ++i) ASSERT_EQ(seen[i], 1) << "primitive " << i;
}

Vector3 random_direction(std::mt19937& rng) {
    std::normal_distribution<float> g;
    for (;;) {
        const Vector3 d{g(rng), g(rng), g(rng)};
        if (length_squared(d) > 1e-6f) return normalize(d);
    }
}

// Adversarial directions: along the axes with +0 and -0 in the other components, in axis
// planes, and general.
Vector3 adversarial_direction(std::mt19937& rng, int i) {
    std::uniform_int_distribution<int> pick(0, 7);
    const float s = pick(rng) % 2 ? 1.0f : -1.0f;
    switch (i % 6) {
        case 0:
            return {s, 0.0f, -0.0f};
        case 1:
            return {-0.0f, s, 0.0f};
        case 2:
            return -Vector3{0, 0, s};  // -0 in x and y
        case 3:
            return normalize(Vector3{s, 1, -0.0f});
        case 4:
            return normalize(Vector3{0.0f, s, -1});
        default:
            return random_direction(rng);
    }
}

TEST(WideBvh, NodesAreFourCacheLines) {
    EXPECT_EQ(sizeof(WideBvhNode), 256u);
    EXPECT_EQ(alignof(WideBvhNode), 64u);
}

TEST(WideBvh, NoPrimitivesGivesAnEmptyTreeThatNothingHits) {
    const WideBvh bvh = build_wide_bvh({});
    EXPECT_TRUE(bvh.nodes.empty());
    EXPECT_TRUE(bvh.bounds().is_empty());
    const Ray ray{{0, 0, 0}, {0, 0, 1}};
    EveryPath paths;
    paths.run([&](SimdPath) {
        EXPECT_FALSE(bvh_closest_hit(
            bvh, ray, {}, [](std::uint32_t, Interval) { return std::optional<float>(1); }));
        EXPECT_FALSE(bvh_any_hit(bvh, ray, {}, [](std::uint32_t, Interval) { return true; }));
    });
}

TEST(WideBvh, OnePrimitiveIsTheRootsOnlyChild) {
    const std::vector<Bounds3> b{{{0, 0, 0}, {1, 1, 1}}};
    const WideBvh bvh = build_wide_bvh(b);
    ASSERT_EQ(bvh.nodes.size(), 1u);
    EXPECT_TRUE(bvh.nodes[0].is_leaf(0));
    EXPECT_EQ(bvh.nodes[0].count[0], 1);
    for (int k = 1; k < kWideBvhWidth; ++k) EXPECT_EQ(bvh.nodes[0].count[k], 0);
    expect_valid(bvh, b);
    EveryPath paths;
    paths.run([&](SimdPath) {
        EXPECT_EQ(with_wide_bvh(bvh, b, Ray{{0.5f, 0.5f, -1}, {0, 0, 1}}, {}).t, 1.0f);
        EXPECT_FALSE(with_wide_bvh(bvh, b, Ray{{1.5f, 0.5f, -1}, {0, 0, 1}}, {}).hit);
    });
}

TEST(WideBvh, CollapseKeepsTheBinaryLeavesAndFillsNodes) {
    const std::vector<Bounds3> b = random_boxes(5000, 1);
    const Bvh binary = build_bvh(b);
    std::vector<std::pair<std::uint32_t, std::uint32_t>> binary_leaves, wide_leaves;
    for (const BvhNode& n : binary.nodes)
        if (n.is_leaf()) binary_leaves.emplace_back(n.offset, n.count);
    const WideBvh wide = collapse_to_wide_bvh(binary);
    expect_valid(wide, b);
    EXPECT_EQ(wide.primitive_indices, binary.primitive_indices);
    EXPECT_EQ(wide.root_bounds.min, binary.nodes[0].bounds.min);
    EXPECT_EQ(wide.root_bounds.max, binary.nodes[0].bounds.max);
    std::size_t slots = 0;
    for (const WideBvhNode& n : wide.nodes) {
        for (int k = 0; k < kWideBvhWidth; ++k) {
            if (n.is_leaf(k) && n.count[k] > 0)
                wide_leaves.emplace_back(n.child[k] & ~kWideLeaf, n.count[k]);
            slots += !(n.is_leaf(k) && n.count[k] == 0);
        }
    }
    std::sort(binary_leaves.begin(), binary_leaves.end());
    std::sort(wide_leaves.begin(), wide_leaves.end());
    EXPECT_EQ(wide_leaves, binary_leaves);
    // Opening the largest child until all are used fills most slots; nodes over binary nodes
    // whose children are both leaves keep two.
    EXPECT_GT(double(slots) / double(kWideBvhWidth * wide.nodes.size()), 0.5);
}

// The summed surface area of the wide nodes' boxes (the root's, and each interior child's as its
// parent stores it): the SAH cost of the node tests, which the collapse minimises.
double node_area(const WideBvh& bvh) {
    double sum = bvh.root_bounds.surface_area();
    for (const WideBvhNode& n : bvh.nodes)
        for (int k = 0; k < kWideBvhWidth; ++k)
            if (!n.is_leaf(k)) sum += n.child_bounds(k).surface_area();
    return sum;
}

// The least node_area over every way of cutting the binary tree into wide nodes, by exhaustive
// search: a wide node made of binary node n has as children a frontier of n's left subtree and
// one of its right subtree (a frontier of a subtree: its root, or a frontier of each of the
// root's children), at most kWideBvhWidth in all.
class LeastNodeArea {
public:
    explicit LeastNodeArea(const Bvh& binary) : nodes_(binary.nodes) {}

    double of_root() { return nodes_[0].is_leaf() ? nodes_[0].bounds.surface_area() : as_node(0); }

private:
    using Frontier = std::vector<std::uint32_t>;

    double as_node(std::uint32_t n) {
        if (const auto known = memo_.find(n); known != memo_.end()) return known->second;
        double best = kInfinity;
        for (const Frontier& left : frontiers(n + 1, kWideBvhWidth - 1))
            for (const Frontier& right : frontiers(nodes_[n].offset, kWideBvhWidth - left.size())) {
                double sum = 0;
                for (const Frontier* side : {&left, &right})
                    for (const std::uint32_t c : *side)
                        if (!nodes_[c].is_leaf()) sum += as_node(c);
                best = std::min(best, sum);
            }
        return memo_[n] = double(nodes_[n].bounds.surface_area()) + best;
    }

    std::vector<Frontier> frontiers(std::uint32_t n, std::size_t limit) const {
        std::vector<Frontier> out{{n}};
        if (nodes_[n].is_leaf() || limit < 2) return out;
        for (const Frontier& left : frontiers(n + 1, limit - 1))
            for (const Frontier& right : frontiers(nodes_[n].offset, limit - left.size())) {
                Frontier f = left;
                f.insert(f.end(), right.begin(), right.end());
                out.push_back(f);
            }
        return out;
    }

    const LargeVector<BvhNode>& nodes_;
    std::map<std::uint32_t, double> memo_;
};

TEST(WideBvh, CollapseMinimisesTheNodesSurfaceArea) {
    for (const int count : {3, 9, 17, 30, 45}) {
        for (unsigned seed = 1; seed <= 4; ++seed) {
            BvhBuildOptions options;
            options.max_leaf_size = 1 + int(seed % 2);
            const std::vector<Bounds3> b = random_boxes(count, seed, 10, 1 + float(seed));
            const Bvh binary = build_bvh(b, options);
            const double least = LeastNodeArea(binary).of_root();
            const WideBvh wide = collapse_to_wide_bvh(binary);
            expect_valid(wide, b);
            // The collapse keeps its sums in float: equal up to their rounding.
            EXPECT_NEAR(node_area(wide), least, 1e-5 * least) << count << " boxes, seed " << seed;
        }
    }
}

TEST(WideBvh, NoLeafMixesKinds) {
    const std::vector<Bounds3> b = random_boxes(4000, 6, 10, 2);  // overlapping: mixed ranges
    std::vector<std::uint8_t> kinds(b.size());
    for (std::size_t i = 0; i < b.size(); ++i) kinds[i] = std::uint8_t(i % 3 == 0);
    const WideBvh bvh = build_wide_bvh(b, kWideBvhTriangleBuildOptions, kinds);
    expect_valid(bvh, b, 16);  // four blocks of four
    for (const WideBvhNode& n : bvh.nodes) {
        for (int k = 0; k < kWideBvhWidth; ++k) {
            if (!n.is_leaf(k) || n.count[k] == 0) continue;
            const std::uint32_t first = n.child[k] & ~kWideLeaf;
            for (std::uint32_t i = 1; i < n.count[k]; ++i)
                ASSERT_EQ(kinds[bvh.primitive_indices[first + i]],
                          kinds[bvh.primitive_indices[first]]);
        }
    }
}

TEST(WideBvh, PackingTurnsLeavesOfTrianglesIntoBlocksInIdOrder) {
    // Small triangles in random boxes; every fourth primitive is not a triangle.
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(-10, 10), small(-0.5f, 0.5f);
    std::vector<std::array<Point3, 3>> corners;
    std::vector<Bounds3> b;
    std::vector<std::uint8_t> kinds;
    for (int i = 0; i < 3000; ++i) {
        const Point3 c{u(rng), u(rng), u(rng)};
        const auto corner = [&] { return c + Vector3{small(rng), small(rng), small(rng)}; };
        corners.push_back({corner(), corner(), corner()});
        b.push_back(merge(Bounds3::of(corners[i][0], corners[i][1]), corners[i][2]));
        kinds.push_back(i % 4 == 0 ? 0 : 1);
    }
    WideBvh bvh = build_wide_bvh(b, kWideBvhTriangleBuildOptions, kinds);
    pack_block_leaves(bvh, kinds, [&](std::uint32_t i) {
        EXPECT_EQ(kinds[i], kBlockTriangle);  // asked only for triangles
        return BlockTriangle{corners[i][0], corners[i][1], corners[i][2], 100000 + i};
    });
    std::vector<int> seen(b.size());
    for (const WideBvhNode& n : bvh.nodes) {
        for (int k = 0; k < kWideBvhWidth; ++k) {
            if (!n.is_leaf(k) || n.count[k] == 0) continue;
            const Bounds3 box = n.child_bounds(k);
            if (leaf_kind(n.child[k]) == kWidePrimitiveLeaf) {
                for (const std::uint32_t i : leaf_primitives(bvh, n.child[k], n.count[k])) {
                    EXPECT_EQ(kinds[i], 0);
                    ++seen[i];
                }
                continue;
            }
            std::uint32_t previous = 0;
            int lanes = 0;
            for (const TriangleBlock& block : leaf_blocks(bvh, n.child[k], n.count[k])) {
                for (int lane = 0; lane < 4; ++lane) {
                    if (block.id[lane] == kNoTriangle) continue;
                    ++lanes;
                    ASSERT_GT(block.id[lane], previous) << "lanes run in ascending id";
                    previous = block.id[lane];
                    const std::uint32_t i = block.id[lane] - 100000;
                    EXPECT_EQ(kinds[i], 1);
                    ++seen[i];
                    for (int c = 0; c < 3; ++c) {
                        EXPECT_EQ(block.corner(lane, c), corners[i][std::size_t(c)]);
                        EXPECT_TRUE(box.contains(corners[i][std::size_t(c)]));
                    }
                }
            }
            // Blocks are filled before a new one starts.
            EXPECT_EQ((lanes + 3) / 4, int(n.count[k]));
        }
    }
    for (std::size_t i = 0; i < seen.size(); ++i) ASSERT_EQ(seen[i], 1) << "primitive " << i;
    EXPECT_EQ(bvh.primitive_indices.size(), b.size() / 4);  // only the leaves of other shapes
}

TEST(WideBvh, LeafSizeOptionIsRespected) {
    const std::vector<Bounds3> b = random_boxes(3000, 2);
    for (const int leaf : {1, 2, 8}) {
        BvhBuildOptions options;
        options.max_leaf_size = leaf;
        expect_valid(build_wide_bvh(b, options), b, leaf);
    }
}

TEST(WideBvh, AMillionCoincidentBoxesTerminateWithSmallLeaves) {
    const std::vector<Bounds3> b(kCoincidentCount, Bounds3{{1, 2, 3}, {1, 2, 3}});  // no extent
    const WideBvh bvh = build_wide_bvh(b);
    expect_valid(bvh, b);
    // A ray through the point meets them all; any hit stops at the first.
    int calls = 0;
    EXPECT_TRUE(bvh_any_hit(bvh, Ray{{1, 2, 0}, {0, 0, 1}}, {}, [&](std::uint32_t, Interval) {
        ++calls;
        return true;
    }));
    EXPECT_EQ(calls, 1);
}

TEST(WideBvh, SkewedAndNonFiniteInputStaysValid) {
    std::vector<Bounds3> b;
    for (int i = 0; i < 120; ++i) {  // exponentially spaced: SAH cuts one off at a time
        const float x = std::ldexp(1.0f, i);
        b.push_back({{x, 0, 0}, {x * 1.01f, 1, 1}});
    }
    BvhBuildOptions options;
    options.max_leaf_size = 1;
    expect_valid(build_wide_bvh(b, options), b, 1);

    std::vector<Bounds3> odd = random_boxes(200, 3);
    odd[5] = Bounds3{};  // empty
    odd[9] = {{-kInfinity, 0, 0}, {kInfinity, 1, 1}};
    odd[11].min.x = kNaN;
    const WideBvh bvh = build_wide_bvh(odd);
    std::vector<std::uint32_t> sorted(bvh.primitive_indices.begin(), bvh.primitive_indices.end());
    std::sort(sorted.begin(), sorted.end());
    for (std::uint32_t i = 0; i < sorted.size(); ++i) ASSERT_EQ(sorted[i], i);
}

// Big enough for the blocked binning and partition (2^16) and the subtree tasks (2^12).
TEST(WideBvh, BuildIsIdenticalForAnyThreadCount) {
    std::vector<Bounds3> b = random_boxes(testing::kUnderSanitizer ? 60'000 : 300'000, 4, 100, 2);
    // Duplicates and a cluster, so that median splits and the fallbacks run as well.
    for (int i = 0; i < 20'000; ++i) b.push_back({{5, 5, 5}, {6, 6, 6}});
    Bvh reference_binary;
    WideBvh reference;
    on_threads(1, [&] {
        reference_binary = build_bvh(b);
        reference = build_wide_bvh(b);
    });
    expect_valid(reference, b);
    for (const int threads : {2, 3, 8}) {
        Bvh binary;
        WideBvh wide;
        on_threads(threads, [&] {
            binary = build_bvh(b);
            wide = build_wide_bvh(b);
        });
        ASSERT_EQ(binary.nodes.size(), reference_binary.nodes.size()) << threads << " threads";
        EXPECT_EQ(std::memcmp(binary.nodes.data(), reference_binary.nodes.data(),
                              binary.nodes.size() * sizeof(BvhNode)),
                  0)
            << threads << " threads";
        EXPECT_EQ(binary.primitive_indices, reference_binary.primitive_indices);
        ASSERT_EQ(binary.node_ranges.size(), reference_binary.node_ranges.size());
        for (std::size_t i = 0; i < binary.node_ranges.size(); ++i) {
            EXPECT_EQ(binary.node_ranges[i].begin, reference_binary.node_ranges[i].begin);
            EXPECT_EQ(binary.node_ranges[i].parent, reference_binary.node_ranges[i].parent);
        }
        ASSERT_EQ(wide.nodes.size(), reference.nodes.size()) << threads << " threads";
        EXPECT_EQ(std::memcmp(wide.nodes.data(), reference.nodes.data(),
                              wide.nodes.size() * sizeof(WideBvhNode)),
                  0)
            << threads << " threads";
        EXPECT_EQ(wide.primitive_indices, reference.primitive_indices);
    }
}

// The build's node ranges, which the collapse solves in parallel from the leaves up: they tile the
// nodes in order, and a node's children are in its own range or begin a range below it.
TEST(WideBvh, NodeRangesHoldEachNodesChildren) {
    const std::vector<Bounds3> b =
        random_boxes(testing::kUnderSanitizer ? 60'000 : 200'000, 4, 100, 3);
    const Bvh bvh = build_bvh(b);
    const std::vector<BvhNodeRange>& ranges = bvh.node_ranges;
    ASSERT_GT(ranges.size(), 10u);  // subtrees were built as tasks
    std::vector<std::int32_t> range_of(bvh.nodes.size(), -1);
    std::vector<std::int32_t> starting(bvh.nodes.size(), -1);
    std::uint32_t next = 0;
    for (std::size_t r = 0; r < ranges.size(); ++r) {
        ASSERT_EQ(ranges[r].begin, next);
        ASSERT_LT(ranges[r].begin, ranges[r].end);
        ASSERT_LT(ranges[r].parent, std::int32_t(r));
        ASSERT_EQ(ranges[r].parent < 0, r == 0);
        for (std::uint32_t n = ranges[r].begin; n < ranges[r].end; ++n)
            range_of[n] = std::int32_t(r);
        starting[ranges[r].begin] = std::int32_t(r);
        next = ranges[r].end;
    }
    ASSERT_EQ(next, bvh.nodes.size());
    for (std::uint32_t n = 0; n < bvh.nodes.size(); ++n) {
        if (bvh.nodes[n].is_leaf()) continue;
        const std::int32_t r = range_of[n];
        EXPECT_EQ(range_of[n + 1], r) << n;
        const std::uint32_t second = bvh.nodes[n].offset;
        EXPECT_TRUE(range_of[second] == r ||
                    (starting[second] >= 0 && ranges[std::size_t(starting[second])].parent == r))
            << n;
    }
}

// The node test of every kernel against slab_hit, child by child, on random nodes and on rays
// with zero, -0, infinite and NaN components.
#ifdef GLINT_WIDE_BVH_HAS_SIMD
// The AVX2 kernel, which only target("avx2") functions can run.
__attribute__((target("avx2"))) unsigned avx2_node_test(const WideBvhNode& node, const BvhRay& r,
                                                        float t_min, float t_max, float* t_near) {
    return wide_bvh::Avx2Kernel::test(node, wide_bvh::Avx2Kernel::Ray(r), t_min, t_max, t_near);
}
#endif

TEST(WideBvh, NodeTestKernelsAgreeWithSlabHitBitForBit) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(-4, 4);
    std::uniform_int_distribution<int> pick(0, 9);
    const auto coordinate = [&] {
        const int p = pick(rng);
        return p == 0 ? 0.0f : p == 1 ? -0.0f : p == 2 ? 1.0f : u(rng);  // ties with the origin
    };
    int hits = 0;
    for (int i = 0; i < 20000; ++i) {
        WideBvhNode node{};
        for (int k = 0; k < kWideBvhWidth; ++k) {
            Point3 a{coordinate(), coordinate(), coordinate()};
            Point3 b{coordinate(), coordinate(), coordinate()};
            Bounds3 box = Bounds3::of(a, b);
            if (pick(rng) == 0) box = Bounds3{};  // an unused slot
            node.planes[0][k] = box.min.x, node.planes[1][k] = box.min.y;
            node.planes[2][k] = box.min.z, node.planes[3][k] = box.max.x;
            node.planes[4][k] = box.max.y, node.planes[5][k] = box.max.z;
        }
        Vector3 d{coordinate(), coordinate(), coordinate()};
        if (i % 7 == 0) d = adversarial_direction(rng, i);
        if (i % 101 == 0) d.x = kNaN;
        if (i % 103 == 0) d.y = kInfinity;
        const Ray ray{{coordinate(), coordinate(), coordinate()}, d};
        const BvhRay r(ray);
        const float t_min = pick(rng) < 8 ? 0.0f : u(rng);
        const float t_max = pick(rng) < 5 ? kInfinity : std::abs(u(rng));

        alignas(32) float scalar_t[kWideBvhWidth];
        const unsigned scalar = wide_bvh::ScalarKernel::test(node, wide_bvh::ScalarKernel::Ray(r),
                                                             t_min, t_max, scalar_t);
        for (int k = 0; k < kWideBvhWidth; ++k) {
            const bool expected = slab_hit(node.child_bounds(k), r, t_min, t_max);
            ASSERT_EQ(((scalar >> k) & 1) != 0, expected) << "ray " << i << " child " << k;
        }
        hits += std::popcount(scalar);
#ifdef GLINT_WIDE_BVH_HAS_SIMD
        alignas(32) float sse_t[kWideBvhWidth];
        const unsigned sse =
            wide_bvh::SseKernel::test(node, wide_bvh::SseKernel::Ray(r), t_min, t_max, sse_t);
        ASSERT_EQ(sse, scalar) << "ray " << i;
        ASSERT_EQ(std::memcmp(sse_t, scalar_t, sizeof scalar_t), 0) << "ray " << i;
        if (simd_path_supported(SimdPath::avx2)) {
            alignas(32) float avx2_t[kWideBvhWidth];
            ASSERT_EQ(avx2_node_test(node, r, t_min, t_max, avx2_t), scalar) << "ray " << i;
            ASSERT_EQ(std::memcmp(avx2_t, scalar_t, sizeof scalar_t), 0) << "ray " << i;
        }
#endif
    }
    EXPECT_GT(hits, 5000);
}

// Closest hit (t and index, ties to the lower index) and any hit equal brute force on every
// path, and every path visits the same primitives in the same order.
void expect_agreement(const std::vector<Bounds3>& boxes, const WideBvh& bvh,
                      const std::vector<std::pair<Ray, Interval>>& rays, int min_hits) {
    EveryPath paths;
    std::vector<std::vector<std::uint32_t>> first_path_order(rays.size());
    bool first = true;
    paths.run([&](SimdPath path) {
        int hits = 0;
        for (std::size_t i = 0; i < rays.size(); ++i) {
            const auto& [ray, range] = rays[i];
            const Nearest expected = brute_force(boxes, ray, range);
            std::vector<std::uint32_t> order;
            const Nearest got = with_wide_bvh(bvh, boxes, ray, range, &order);
            ASSERT_EQ(got.hit, expected.hit) << simd_path_name(path) << " ray " << i;
            ASSERT_EQ(any_with_wide_bvh(bvh, boxes, ray, range), expected.hit)
                << simd_path_name(path) << " ray " << i;
            if (first) {
                first_path_order[i] = std::move(order);
            } else {
                ASSERT_EQ(order, first_path_order[i]) << simd_path_name(path) << " ray " << i;
            }
            if (!expected.hit) continue;
            ++hits;
            ASSERT_EQ(got.t, expected.t) << simd_path_name(path) << " ray " << i;
            ASSERT_EQ(got.index, expected.index) << simd_path_name(path) << " ray " << i;
        }
        EXPECT_GT(hits, min_hits) << simd_path_name(path);
        first = false;
    });
}

TEST(WideBvh, ClosestAndAnyHitMatchBruteForceOnRandomRaysOnEveryPath) {
    for (const unsigned seed : {1u, 2u}) {
        const auto boxes = random_boxes(3000, seed, 10, 0.5f);
        const WideBvh bvh = build_wide_bvh(boxes);
        std::mt19937 rng(seed + 100);
        std::uniform_real_distribution<float> u(-1, 1), unit(0, 1);
        std::vector<std::pair<Ray, Interval>> rays;
        for (int i = 0; i < 2000; ++i) {
            const float reach = i % 3 == 0 ? 30.0f : 12.0f;
            const Ray ray{{u(rng) * reach, u(rng) * reach, u(rng) * reach},
                          i % 4 == 0 ? adversarial_direction(rng, i) : random_direction(rng)};
            rays.push_back({ray, {}});
            rays.push_back({ray, {unit(rng) * 3, 4 + 10 * unit(rng)}});
        }
        expect_agreement(boxes, bvh, rays, 800);
    }
}

TEST(WideBvh, RaysStartingOnBoxesAndRunningAlongTheirFacesMatchBruteForce) {
    const auto boxes = box_grid(8);
    const WideBvh bvh = build_wide_bvh(boxes);
    std::mt19937 rng(9);
    std::uniform_int_distribution<int> grid(0, 8);
    std::uniform_real_distribution<float> u(0, 8);
    std::vector<std::pair<Ray, Interval>> rays;
    for (int i = 0; i < 4000; ++i) {
        // On a grid plane (a face shared by two boxes, or a flat box), on an edge, or a corner.
        Point3 o{u(rng), u(rng), u(rng)};
        if (i % 2 == 0) o.x = float(grid(rng));
        if (i % 3 == 0) o.y = float(grid(rng));
        if (i % 5 == 0) o.z = float(grid(rng));
        if (i % 11 == 0) o.y = -0.0f;                // the plane y = 0 from its negative-zero side
        if (i % 7 == 0) o = o + Vector3{-12, 0, 0};  // from outside
        rays.push_back({{o, adversarial_direction(rng, i)}, {}});
    }
    expect_agreement(boxes, bvh, rays, 3000);
}

TEST(WideBvh, AnyHitStopsAtTheFirstHit) {
    const auto boxes = random_boxes(500, 4, 1, 0.2f);  // dense: a ray through the middle hits many
    const WideBvh bvh = build_wide_bvh(boxes);
    const Ray ray{{-20, 0.1f, 0.2f}, {1, 0, 0}};
    EveryPath paths;
    paths.run([&](SimdPath) {
        int calls = 0, hits = 0;
        EXPECT_TRUE(bvh_any_hit(bvh, ray, {}, [&](std::uint32_t k, Interval r) {
            ++calls;
            const bool hit = box_hit(boxes[k], ray, r).has_value();
            hits += hit;
            return hit;
        }));
        EXPECT_EQ(hits, 1);
        EXPECT_LT(calls, 100);
    });
}

TEST(WideBvh, ClosestHitCullsSubtreesBeyondTheNearestHit) {
    // A row of boxes along x: a ray along x needs only the first few.
    std::vector<Bounds3> boxes;
    for (int i = 0; i < 1000; ++i) boxes.push_back({{float(i), 0, 0}, {float(i) + 0.5f, 1, 1}});
    const WideBvh bvh = build_wide_bvh(boxes);
    std::vector<std::uint32_t> visited;
    const Nearest n = with_wide_bvh(bvh, boxes, Ray{{-1, 0.5f, 0.5f}, {1, 0, 0}}, {}, &visited);
    EXPECT_EQ(n.index, 0u);
    EXPECT_LT(visited.size(), 20u);
}

TEST(WideBvh, NaNRaysVisitOnlyRealLeaves) {
    const auto boxes = random_boxes(100, 6);
    const WideBvh bvh = build_wide_bvh(boxes);
    const Ray ray{{kNaN, 0, 0}, {1, kNaN, 0}};
    EveryPath paths;
    paths.run([&](SimdPath) {
        std::vector<int> seen(boxes.size(), 0);
        bvh_closest_hit(bvh, ray, {}, [&](std::uint32_t k, Interval) -> std::optional<float> {
            EXPECT_LT(k, boxes.size());
            if (k < boxes.size()) ++seen[k];
            return std::nullopt;
        });
        for (const int s : seen) EXPECT_LE(s, 1);
    });
}

TEST(SimdPath, ScalarIsAlwaysSupportedAndSwitchable) {
    const SimdPath saved = simd_path();
    EXPECT_TRUE(simd_path_supported(SimdPath::scalar));
    EXPECT_TRUE(set_simd_path(SimdPath::scalar));
    EXPECT_EQ(simd_path(), SimdPath::scalar);
    EXPECT_TRUE(simd_path_supported(best_simd_path()));
    EXPECT_TRUE(set_simd_path(saved));
    EXPECT_EQ(simd_path_name(SimdPath::avx2), "avx2");
}

}  // namespace
}  // namespace glint::wide_bvh_test
