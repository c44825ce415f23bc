// The Embree back end agrees with the brute-force list: the same closest hits (up to Embree's own
// triangle test, see embree_aggregate.h), the same occlusion answers, masks and tie rule.
#include "glint/accel/embree_aggregate.h"

#include <gtest/gtest.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <random>
#include <vector>

#include "common/under_sanitizer.h"
#include "glint/accel/make_aggregate.h"
#include "glint/accel/primitive_list.h"

namespace glint {
namespace {

// A closed UV sphere of triangles: a mesh with shared vertices, as loaders produce.
TriangleMesh sphere_mesh(Point3 center, float radius, int rings) {
    MeshData arrays;
    const int segments = 2 * rings;
    for (int i = 0; i <= rings; ++i) {
        const float theta = 3.14159265f * float(i) / float(rings);
        for (int j = 0; j < segments; ++j) {
            const float phi = 6.28318531f * float(j) / float(segments);
            arrays.positions.push_back(center + radius * Vector3{std::sin(theta) * std::cos(phi),
                                                                 std::cos(theta),
                                                                 std::sin(theta) * std::sin(phi)});
        }
    }
    const auto at = [&](int i, int j) { return std::uint32_t(i * segments + j % segments); };
    for (int i = 0; i < rings; ++i)
        for (int j = 0; j < segments; ++j) {
            arrays.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            arrays.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    MeshBuild built = build_mesh(std::move(arrays));  // drops the poles' zero-area triangles
    EXPECT_TRUE(built.mesh) << built.error;
    return TriangleMesh{built.mesh};
}

// Spheres, boxes, loose triangles, meshes (one shared by two primitives, one under a transform,
// so a user geometry), and two planes; a fifth of them cast no shadow.
std::vector<Primitive> random_scene(int n, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> pos(-10, 10), size(0.05f, 1.5f), unit(0, 1);
    std::vector<Primitive> prims;
    const TriangleMesh shared = sphere_mesh({0, 0, 0}, 1, 6);
    for (int i = 0; i < n; ++i) {
        const Point3 c{pos(rng), pos(rng), pos(rng)};
        const float s = size(rng);
        Primitive p;
        switch (i % 5) {
            case 0:
                p.shape = Sphere{c, s};
                break;
            case 1:
                p.shape = Box{c, c + Vector3{s, s * 0.5f, s * 2}};
                break;
            case 2:
                p.shape = Triangle{{c, c + Vector3{s, 0, 0}, c + Vector3{0, s, s}}};
                break;
            case 3:
                p.shape = i % 50 == 3 ? Shape{Transformed{Transform::translate(to_vector(c)),
                                                          std::make_shared<Shape>(shared)}}
                                      : Shape{sphere_mesh(c, s, 4 + i % 5)};
                break;
            default:
                p.shape = i % 20 == 4 ? Shape{shared} : Shape{Sphere{c, s * 0.5f}};
        }
        if (unit(rng) < 0.2f) p.visibility = kVisibleToCameraRays;  // casts no shadow
        prims.push_back(p);
    }
    prims.push_back({Plane{{0, -11, 0}, {0, 1, 0}}});
    prims.push_back({Plane{{0, 0, 11}, {0, 0, -1}}, kVisibleToCameraRays});
    return prims;
}

bool is_triangle(const Primitive& p) {
    return std::holds_alternative<Triangle>(p.shape) ||
           std::holds_alternative<TriangleMesh>(p.shape);
}

// A hit that Embree's watertight test and glint's Moeller-Trumbore may legitimately see
// differently: on a triangle, right at an edge.
bool grazes_edge(std::span<const Primitive> prims, const Hit& hit) {
    const ShapeHit& h = hit.shape_hit;
    return is_triangle(prims[hit.primitive]) && std::min({h.u, h.v, 1 - h.u - h.v}) < 1e-4f;
}

// Triangle t values are Embree's, a few ulps from glint's; everything else is glint's own.
float tolerance(std::span<const Primitive> prims, const Hit& hit) {
    return is_triangle(prims[hit.primitive]) ? 1e-4f * (1 + hit.shape_hit.t) : 0.0f;
}

TEST(EmbreeAggregate, AgreesWithBruteForceOnRandomScenes) {
    for (const unsigned seed : {3u, 4u}) {
        const auto prims = random_scene(1500, seed);
        const EmbreeAggregate embree(prims);
        const PrimitiveList list(prims);
        std::mt19937 rng(seed + 100);
        std::uniform_real_distribution<float> u(-1, 1);
        int hits = 0, edge_cases = 0, ties = 0, mesh_hits = 0;
        // The brute-force list is slow (its meshes' 60,000 triangles each ray: 31 s for 1,500
        // rays a scene in a release build), and eight times slower under the sanitizers.
        const int rays = testing::kUnderSanitizer ? 200 : 1000;
        for (int i = 0; i < rays; ++i) {
            Vector3 d{u(rng), u(rng), u(rng)};
            if (i % 10 == 0) d = {0, 0, u(rng) < 0 ? -1.0f : 1.0f};  // axis-parallel
            if (length_squared(d) < 1e-4f) continue;
            const Ray ray{{u(rng) * 12, u(rng) * 12, u(rng) * 12}, normalize(d)};
            for (const std::uint32_t mask :
                 {std::uint32_t(kVisibleToCameraRays), std::uint32_t(kVisibleToShadowRays)}) {
                const auto a = embree.intersect(ray, {}, mask);
                const auto b = list.intersect(ray, {}, mask);
                if (a.has_value() != b.has_value()) {
                    ASSERT_TRUE(grazes_edge(prims, a ? *a : *b)) << "ray " << i;
                    ++edge_cases;
                    continue;
                }
                if (!a) continue;
                ++hits;
                EXPECT_NE(prims[a->primitive].visibility & mask, 0u);
                const float tol = std::max(tolerance(prims, *a), tolerance(prims, *b));
                EXPECT_NEAR(a->shape_hit.t, b->shape_hit.t, tol) << "ray " << i;
                if (a->primitive != b->primitive || a->shape_hit.part != b->shape_hit.part) {
                    // Only a tie (here: the mesh shared by two primitives), or an edge shared by
                    // two triangles, may be resolved otherwise.
                    if (std::abs(a->shape_hit.t - b->shape_hit.t) <= tol) {
                        ++ties;
                    } else {
                        EXPECT_TRUE(grazes_edge(prims, *a) || grazes_edge(prims, *b))
                            << "ray " << i;
                        ++edge_cases;
                    }
                    continue;
                }
                if (std::holds_alternative<TriangleMesh>(prims[a->primitive].shape)) {
                    // part and barycentrics as TriangleMesh::intersect gives them.
                    ++mesh_hits;
                    EXPECT_NEAR(a->shape_hit.u, b->shape_hit.u, 1e-3f);
                    EXPECT_NEAR(a->shape_hit.v, b->shape_hit.v, 1e-3f);
                    const SurfacePoint sp =
                        surface_at(prims[a->primitive].shape, ray, a->shape_hit);
                    EXPECT_LT(distance(sp.p, ray.at(a->shape_hit.t)), 1e-3f) << "ray " << i;
                } else if (!is_triangle(prims[a->primitive])) {
                    EXPECT_EQ(a->shape_hit.t, b->shape_hit.t) << "ray " << i;
                    EXPECT_EQ(a->shape_hit.part, b->shape_hit.part) << "ray " << i;
                }
                // Segments that stop short of and just past the hit.
                const float t = b->shape_hit.t;
                if (!grazes_edge(prims, *b)) {
                    EXPECT_EQ(embree.occluded(ray, {0, t * 0.99f}, mask),
                              list.occluded(ray, {0, t * 0.99f}, mask))
                        << "ray " << i;
                    EXPECT_TRUE(embree.occluded(ray, {0, t * 1.01f + 1e-3f}, mask)) << "ray " << i;
                }
            }
            const Interval segment{0, 5};
            const bool occluded = embree.occluded(ray, segment, kVisibleToShadowRays);
            if (occluded != list.occluded(ray, segment, kVisibleToShadowRays)) ++edge_cases;
        }
        EXPECT_GT(hits, rays * 3 / 4);
        EXPECT_GT(mesh_hits, rays / 40);
        EXPECT_LE(edge_cases, 8) << "seed " << seed;  // about one ray in a thousand at most
        EXPECT_LE(ties, hits / 100) << "seed " << seed;
    }
}

// Packets through rtcIntersect8 and rtcOccluded8 (user geometry called for eight rays at once)
// against the same rays one at a time: the same answers, up to Embree's packet triangle test,
// which may see a ray that grazes an edge otherwise.
TEST(EmbreeAggregate, PacketsAgreeWithSingleRays) {
    const auto prims = random_scene(1500, 5);
    const EmbreeAggregate embree(prims);
    std::mt19937 rng(6);
    std::uniform_real_distribution<float> u(-1, 1);
    int hits = 0, blocked = 0, edge_cases = 0;
    const int packets = testing::kUnderSanitizer ? 100 : 400;
    for (int n = 0; n < packets; ++n) {
        const std::size_t size = n % 4 == 3 ? std::size_t(1 + n % 8) : 8;
        std::vector<Ray> rays;
        const Point3 eye{u(rng) * 3, u(rng) * 3, -25};
        const Vector3 centre{u(rng) * 0.3f, u(rng) * 0.3f, 1};
        for (std::size_t i = 0; i < size; ++i) {
            if (n % 2 == 0) {  // a tile of neighbouring eye rays
                const Vector3 d = centre + Vector3{float(i % 4), float(i / 4), 0} * 0.01f;
                rays.push_back({eye, normalize(d)});
            } else {  // scattered
                rays.push_back({{u(rng) * 12, u(rng) * 12, u(rng) * 12},
                                normalize(Vector3{u(rng), u(rng), u(rng) + 0.01f})});
            }
        }
        std::vector<Interval> ranges(size);
        for (std::size_t i = 0; i < size; ++i)
            ranges[i] = i % 3 == 2 ? Interval{0, 20} : Interval{};
        for (const std::uint32_t mask :
             {std::uint32_t(kVisibleToCameraRays), std::uint32_t(kVisibleToShadowRays)}) {
            std::optional<Hit> got[kRayPacketSize];
            embree.intersect_packet(rays, {}, mask, got);
            const unsigned occluded = embree.occluded_packet(rays, ranges.data(), mask);
            ASSERT_EQ(occluded >> size, 0u);
            for (std::size_t i = 0; i < size; ++i) {
                const auto alone = embree.intersect(rays[i], {}, mask);
                const bool alone_blocked = embree.occluded(rays[i], ranges[i], mask);
                blocked += alone_blocked;
                if (got[i].has_value() != alone.has_value() ||
                    bool(occluded >> i & 1) != alone_blocked) {
                    ++edge_cases;
                    continue;
                }
                if (!alone) continue;
                ++hits;
                const float tol = tolerance(prims, *alone);
                EXPECT_NEAR(got[i]->shape_hit.t, alone->shape_hit.t, tol) << "packet " << n;
                if (got[i]->primitive != alone->primitive) {
                    EXPECT_TRUE(grazes_edge(prims, *alone) ||
                                std::abs(got[i]->shape_hit.t - alone->shape_hit.t) <= tol)
                        << "packet " << n;
                    continue;
                }
                if (!is_triangle(prims[alone->primitive])) {  // glint's own test, bit for bit
                    EXPECT_EQ(got[i]->shape_hit.t, alone->shape_hit.t) << "packet " << n;
                    EXPECT_EQ(got[i]->shape_hit.part, alone->shape_hit.part) << "packet " << n;
                }
            }
        }
    }
    EXPECT_GT(hits, packets * 4);
    EXPECT_GT(blocked, packets * 2);
    EXPECT_LE(edge_cases, 4);
}

TEST(EmbreeAggregate, MasksHideWholeMeshesAndShapesFromShadowRays) {
    const std::vector<Primitive> prims{
        {sphere_mesh({0, 0, 5}, 1, 8), kVisibleToCameraRays},
        {Sphere{{0, 0, 10}, 1}, kVisibleToCameraRays},
        {Triangle{{Point3{-1, -1, 15}, Point3{1, -1, 15}, Point3{0, 1, 15}}}},
    };
    const EmbreeAggregate embree(prims);
    const Ray ray{{0, 0, 0}, {0, 0, 1}};
    const auto seen = embree.intersect(ray, {}, kVisibleToCameraRays);
    ASSERT_TRUE(seen);
    EXPECT_EQ(seen->primitive, 0u);
    const auto feeler = embree.intersect(ray, {}, kVisibleToShadowRays);
    ASSERT_TRUE(feeler);
    EXPECT_EQ(feeler->primitive, 2u);
    EXPECT_NEAR(feeler->shape_hit.t, 15, 1e-5f);
    EXPECT_FALSE(embree.occluded(ray, {0, 14}, kVisibleToShadowRays));
    EXPECT_TRUE(embree.occluded(ray, {0, 14}, kVisibleToCameraRays));
    EXPECT_FALSE(embree.intersect(ray, {}, 0));
}

TEST(EmbreeAggregate, EqualDistancesGoToTheLowerIndexAmongGlintShapes) {
    // 20000 coincident spheres: one user geometry, every primitive at the same t.
    std::vector<Primitive> spheres(20000, Primitive{Sphere{{0, 0, 5}, 1}});
    const EmbreeAggregate many(spheres);
    const auto hit = many.intersect({{0, 0, 0}, {0, 0, 1}}, {}, ~0u);
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->shape_hit.t, 4);
    EXPECT_EQ(hit->primitive, 0u);
    // A box face and a plane at the same t, in both orders.
    const Primitive box{Box{{-1, -1, 5}, {1, 1, 6}}}, plane{Plane{{0, 0, 5}, {0, 0, -1}}};
    for (const bool plane_first : {false, true}) {
        const std::vector<Primitive> prims =
            plane_first ? std::vector{plane, box} : std::vector{box, plane};
        const EmbreeAggregate tie(prims);
        const auto h = tie.intersect({{0, 0, 0}, {0, 0, 1}}, {}, ~0u);
        ASSERT_TRUE(h);
        EXPECT_EQ(h->shape_hit.t, 5);
        EXPECT_EQ(h->primitive, 0u) << "plane first: " << plane_first;
    }
}

TEST(EmbreeAggregate, BoundsLeaveOutPlanesAndEmptySceneHitsNothing) {
    const std::vector<Primitive> prims{{Sphere{{1, 2, 3}, 1}}, {Plane{}}};
    const EmbreeAggregate embree(prims);
    EXPECT_EQ(embree.bounds().min, (Point3{0, 1, 2}));
    EXPECT_EQ(embree.bounds().max, (Point3{2, 3, 4}));
    EXPECT_TRUE(embree.intersect({{0, 5, 0}, {0, -1, 0}}, {}, ~0u));  // the plane
    EXPECT_TRUE(embree.occluded({{0, 5, 0}, {0, -1, 0}}, {0, 6}, ~0u));
    const EmbreeAggregate empty({});
    EXPECT_FALSE(empty.intersect({{0, 0, 0}, {0, 0, 1}}, {}, ~0u));
    EXPECT_FALSE(empty.occluded({{0, 0, 0}, {0, 0, 1}}, {}, ~0u));
    EXPECT_GT(empty.memory_bytes(), 0u);
}

TEST(EmbreeAggregate, MemoryGrowsWithTheTrianglesAndCountsEmbreesOwn) {
    const std::vector<Primitive> small{{sphere_mesh({0, 0, 0}, 1, 8)}};
    const std::vector<Primitive> large{{sphere_mesh({0, 0, 0}, 1, 128)}};
    const EmbreeAggregate a(small), b(large);
    const std::size_t triangles = std::get<TriangleMesh>(large[0].shape).data->triangles.size();
    EXPECT_GT(b.memory_bytes(), a.memory_bytes());
    // At least the padded vertex copy and some BVH per triangle, and not absurdly more.
    EXPECT_GT(b.memory_bytes(), 16 * triangles);
    EXPECT_LT(b.memory_bytes(), 1000 * triangles);
}

TEST(EmbreeAggregate, ConcurrentQueriesGiveTheSequentialAnswers) {
    const auto prims = random_scene(600, 9);
    const EmbreeAggregate embree(prims);
    std::vector<Ray> rays;
    std::mt19937 rng(10);
    std::uniform_real_distribution<float> u(-1, 1);
    for (int i = 0; i < 20000; ++i)
        rays.push_back({{u(rng) * 12, u(rng) * 12, u(rng) * 12},
                        normalize(Vector3{u(rng), u(rng), u(rng) + 1e-3f})});
    std::vector<float> sequential(rays.size(), -1);
    for (std::size_t i = 0; i < rays.size(); ++i)
        if (const auto h = embree.intersect(rays[i], {}, kVisibleToCameraRays))
            sequential[i] = h->shape_hit.t;
    std::atomic<int> mismatches{0};
    tbb::parallel_for(std::size_t(0), rays.size(), [&](std::size_t i) {
        const auto h = embree.intersect(rays[i], {}, kVisibleToCameraRays);
        if ((h ? h->shape_hit.t : -1.0f) != sequential[i]) ++mismatches;
    });
    EXPECT_EQ(mismatches, 0);
}

TEST(EmbreeAggregate, IsChosenByName) {
    EXPECT_EQ(accel_from_name("embree"), AccelKind::embree);
    EXPECT_EQ(accel_name(AccelKind::embree), "embree");
    const std::vector<Primitive> prims{{Sphere{{0, 0, 5}, 1}}};
    const auto aggregate = make_aggregate(AccelKind::embree, prims);
    ASSERT_TRUE(aggregate);
    EXPECT_TRUE(aggregate->intersect({{0, 0, 0}, {0, 0, 1}}, {}, ~0u));
}

}  // namespace
}  // namespace glint
