// Each mesh's own BVH against the mesh tested triangle by triangle (ties and occlusion included),
// and binding: which meshes get one, shared by every placement, with the scene's shapes unchanged.
#include "glint/accel/mesh_bvh.h"

#include <gtest/gtest.h>

#include <bit>
#include <random>
#include <vector>

#include "glint/accel/wide_bvh_packet.h"
#include "glint/geometry/simd_path.h"
#include "glint/math/animated_transform.h"

namespace glint {
namespace {

// Small random triangles scattered in a box, a tenth of them repeated (the same triangle twice:
// hits at equal t, where the lower index must win).
std::shared_ptr<const MeshData> scattered_triangles(std::uint32_t count, unsigned seed) {
    MeshData arrays;
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-1, 1);
    for (std::uint32_t i = 0; i < count; ++i) {
        const std::uint32_t v = std::uint32_t(arrays.positions.size());
        if (i % 10 == 9) {
            arrays.triangles.push_back(arrays.triangles.back());
            continue;
        }
        const Vector3 c{u(rng) * 5, u(rng) * 5, u(rng) * 5};
        for (int k = 0; k < 3; ++k)
            arrays.positions.push_back(to_point(c + Vector3{u(rng), u(rng), u(rng)} * 0.5f));
        arrays.triangles.push_back({v, v + 1, v + 2});
    }
    MeshBuild built = build_mesh(std::move(arrays));
    EXPECT_TRUE(built.mesh) << built.error;
    return built.mesh;
}

TEST(MeshBvh, ClosestHitAndOcclusionMatchTheTriangleByTriangleTest) {
    const auto data = scattered_triangles(3000, 11);
    const TriangleMesh plain{data};
    const TriangleMesh traced{data, std::make_shared<const MeshBvh>(data)};
    std::mt19937 rng(12);
    std::uniform_real_distribution<float> u(-1, 1);
    int hits = 0, ties = 0;
    for (int i = 0; i < 3000; ++i) {
        const Ray ray{{u(rng) * 8, u(rng) * 8, u(rng) * 8},
                      normalize(Vector3{u(rng), u(rng), u(rng) + 0.01f})};
        // Every other ray stops short of its far end.
        const Interval range = i % 2 ? Interval{0, 6} : Interval{};
        const auto expected = plain.intersect(ray, range);
        const auto got = traced.intersect(ray, range);
        ASSERT_EQ(bool(expected), bool(got)) << "ray " << i;
        ASSERT_EQ(bool(expected), traced.occluded(ray, range)) << "ray " << i;
        if (!expected) continue;
        ++hits;
        ties += expected->part % 10 == 8;  // the triangle before a repeated one
        ASSERT_EQ(got->t, expected->t) << "ray " << i;
        ASSERT_EQ(got->part, expected->part) << "ray " << i;
        ASSERT_EQ(got->u, expected->u) << "ray " << i;
        ASSERT_EQ(got->v, expected->v) << "ray " << i;
    }
    EXPECT_GT(hits, 300);  // the comparison saw real hits, and ties among them
    EXPECT_GT(ties, 10);
}

// Packets of up to eight rays, each lane against the same ray traced alone, bit for bit, on every
// SIMD path (packets on AVX2, one by one elsewhere): a camera's tile (coherent), scattered rays
// (incoherent, mixed direction signs), rays along the axes (zero components), rays whose ranges
// end early, and packets of every size.
TEST(MeshBvh, PacketsHitWhatTheirRaysHitAlone) {
    const auto data = scattered_triangles(3000, 21);
    const MeshBvh bvh(data);
    std::mt19937 rng(22);
    std::uniform_real_distribution<float> u(-1, 1);
    const auto packet_of = [&](int kind, std::size_t size, std::vector<Ray>& rays,
                               std::vector<Interval>& ranges) {
        rays.clear();
        ranges.clear();
        const Point3 eye{u(rng) * 2, u(rng) * 2, 12};
        for (std::size_t i = 0; i < size; ++i) {
            Vector3 d;
            if (kind == 0) {  // a 4x2 tile of neighbouring pixels
                d = normalize(Vector3{u(rng) * 0.3f + float(i % 4) * 0.002f,
                                      u(rng) * 0.3f + float(i / 4) * 0.002f, -1});
            } else if (kind == 1) {
                d = normalize(Vector3{u(rng), u(rng), u(rng) + 0.01f});
            } else {
                const float sign = i % 2 ? 1.0f : -1.0f;
                const std::size_t axis = i % 3;
                d = Vector3{axis == 0 ? sign : 0, axis == 1 ? sign : 0, axis == 2 ? sign : 0};
            }
            const Point3 o = kind == 0 ? eye : Point3{u(rng) * 6, u(rng) * 6, u(rng) * 6};
            rays.push_back({o, d});
            ranges.push_back(i % 3 == 2 ? Interval{0, 8} : Interval{});
        }
    };
    const SimdPath saved = simd_path();
    for (const SimdPath path : kSimdPaths) {
        if (!set_simd_path(path)) continue;
        int hits = 0, blocked = 0;
        std::vector<Ray> rays;
        std::vector<Interval> ranges;
        for (int n = 0; n < 600; ++n) {
            const std::size_t size = n % 5 == 4 ? std::size_t(1 + n % 8) : 8;
            packet_of(n % 3, size, rays, ranges);
            std::optional<ShapeHit> got[kRayPacketSize];
            bvh.intersect_packet(rays, ranges.data(), got);
            const unsigned occluded = bvh.occluded_packet(rays, ranges.data());
            ASSERT_EQ(occluded >> size, 0u);
            for (std::size_t i = 0; i < size; ++i) {
                const auto expected = bvh.intersect(rays[i], ranges[i]);
                ASSERT_EQ(bool(got[i]), bool(expected)) << "packet " << n << " lane " << i;
                ASSERT_EQ(bool(occluded >> i & 1), bvh.occluded(rays[i], ranges[i]))
                    << "packet " << n << " lane " << i;
                if (!expected) continue;
                ++hits;
                ASSERT_EQ(got[i]->t, expected->t) << "packet " << n << " lane " << i;
                ASSERT_EQ(got[i]->part, expected->part) << "packet " << n << " lane " << i;
                ASSERT_EQ(got[i]->u, expected->u) << "packet " << n << " lane " << i;
                ASSERT_EQ(got[i]->v, expected->v) << "packet " << n << " lane " << i;
            }
            blocked += std::popcount(occluded);
        }
        EXPECT_GT(hits, 500) << simd_path_name(path);  // real hits in every kind of packet
        EXPECT_EQ(blocked, hits) << simd_path_name(path);
    }
    set_simd_path(saved);
}

struct Placements {
    std::shared_ptr<const MeshData> mesh = scattered_triangles(200, 3);
    std::shared_ptr<const Shape> child = std::make_shared<const Shape>(TriangleMesh{mesh});
    std::vector<Primitive> primitives{
        {TriangleMesh{mesh}},
        {Transformed(Transform::translate({20, 0, 0}), child)},
        {Transformed(Transform::translate({-20, 0, 0}), child)},
        {Moving(std::make_shared<const AnimatedTransform>(Transform::translate({0, 20, 0})),
                child)},
        {Csg{CsgOperation::union_of, child, std::make_shared<const Shape>(Sphere{{0, 0, 0}, 1})}},
        {Sphere{{0, 0, 30}, 1}},
    };
};

const TriangleMesh& mesh_in(const Shape& shape) {
    if (const auto* t = std::get_if<Transformed>(&shape)) return std::get<TriangleMesh>(*t->shape);
    if (const auto* m = std::get_if<Moving>(&shape)) return std::get<TriangleMesh>(*m->shape);
    if (const auto* c = std::get_if<Csg>(&shape)) return std::get<TriangleMesh>(*c->a);
    return std::get<TriangleMesh>(shape);
}

TEST(MeshBvh, EveryPlacementOfAMeshSharesOneTreeAndTheSceneKeepsNone) {
    Placements scene;
    std::vector<Primitive> world = scene.primitives;
    const MeshBvhBinding binding = bind_mesh_bvhs(world, [](const Shape&) { return false; });
    EXPECT_EQ(binding.meshes, 1u);
    EXPECT_GT(binding.memory_bytes, 0u);
    // The top-level mesh is left to the scene's structure, which splits it into triangles.
    EXPECT_FALSE(std::get<TriangleMesh>(world[0].shape).accelerator);
    const auto* tree = mesh_in(world[1].shape).accelerator.get();
    ASSERT_NE(tree, nullptr);
    for (int p = 2; p <= 4; ++p) EXPECT_EQ(mesh_in(world[p].shape).accelerator.get(), tree);
    // The two instances still share one child.
    EXPECT_EQ(std::get<Transformed>(world[1].shape).shape,
              std::get<Transformed>(world[2].shape).shape);
    // An operand without a mesh is not copied.
    EXPECT_EQ(std::get<Csg>(world[4].shape).b, std::get<Csg>(scene.primitives[4].shape).b);
    // The scene's own shapes are untouched: plain data.
    EXPECT_EQ(std::get<Transformed>(scene.primitives[1].shape).shape, scene.child);
    EXPECT_FALSE(std::get<TriangleMesh>(*scene.child).accelerator);
}

TEST(MeshBvh, TopLevelMeshesAreBoundWhenAskedAndOtherShapesStayAsTheyAre) {
    Placements scene;
    std::vector<Primitive> world = scene.primitives;
    const MeshBvhBinding binding = bind_mesh_bvhs(world, [](const Shape&) { return true; });
    EXPECT_EQ(binding.meshes, 1u);
    EXPECT_EQ(std::get<TriangleMesh>(world[0].shape).accelerator.get(),
              mesh_in(world[1].shape).accelerator.get());
    EXPECT_TRUE(std::holds_alternative<Sphere>(world[5].shape));

    std::vector<Primitive> no_meshes{{Sphere{{0, 0, 0}, 1}}};
    EXPECT_EQ(bind_mesh_bvhs(no_meshes, [](const Shape&) { return true; }).meshes, 0u);
}

TEST(MeshBvh, BoundShapesHitWhatTheSceneShapesHit) {
    Placements scene;
    std::vector<Primitive> world = scene.primitives;
    bind_mesh_bvhs(world, [](const Shape&) { return true; });
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(-1, 1);
    int hits = 0;
    for (std::size_t p = 0; p < world.size(); ++p) {
        const Point3 c = bounds(world[p].shape).center();
        for (int i = 0; i < 300; ++i) {
            const Vector3 d = normalize(Vector3{u(rng), u(rng), u(rng) + 0.01f});
            Ray ray{c - d * 12 + Vector3{u(rng), u(rng), u(rng)} * 2, d};
            ray.time = 0.5f;
            const auto expected = intersect(scene.primitives[p].shape, ray, {});
            const auto got = intersect(world[p].shape, ray, {});
            ASSERT_EQ(bool(expected), bool(got)) << "primitive " << p << " ray " << i;
            if (!expected) continue;
            ++hits;
            ASSERT_EQ(got->t, expected->t) << "primitive " << p << " ray " << i;
            ASSERT_EQ(got->part, expected->part) << "primitive " << p << " ray " << i;
        }
    }
    EXPECT_GT(hits, 300);
}

}  // namespace
}  // namespace glint
