// Triangle meshes: building (validation, degenerate triangles), worked hits on a quad, smooth
// and flat normals, and the shared shape properties. Its BVH is tested in tests/accel.
#include "glint/geometry/triangle_mesh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "glint/geometry/vertex_normals.h"
#include "shape_property_checks.h"

namespace glint {
namespace {

// The unit quad in the xy plane, facing +z: triangles (0,1,2) and (0,2,3).
MeshData quad_arrays() {
    MeshData m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    m.triangles = {{0, 1, 2}, {0, 2, 3}};
    return m;
}

TriangleMesh build(MeshData arrays) {
    MeshBuild built = build_mesh(std::move(arrays));
    EXPECT_TRUE(built.mesh) << built.error;
    return TriangleMesh{built.mesh};
}

TEST(TriangleMesh, WorkedHitOnTheQuadsSecondTriangle) {
    MeshData arrays = quad_arrays();
    arrays.uvs = {{0, 0}, {2, 0}, {2, 2}, {0, 2}};
    const TriangleMesh mesh = build(arrays);
    EXPECT_EQ(mesh.bounds().min, (Point3{0, 0, 0}));
    EXPECT_EQ(mesh.bounds().max, (Point3{1, 1, 0}));
    // Straight down onto (0.25, 0.5) from z = 2: t = 2. In triangle (0,2,3) the point is
    // 0.5 v0 + 0.25 v2 + 0.25 v3, so u (vertex 2's weight) = 0.25 and v (vertex 3's) = 0.25.
    const Ray ray{{0.25f, 0.5f, 2}, {0, 0, -1}};
    const auto hit = mesh.intersect(ray, {});
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit->t, 2);
    EXPECT_EQ(hit->part, 1u);
    EXPECT_FLOAT_EQ(hit->u, 0.25f);
    EXPECT_FLOAT_EQ(hit->v, 0.25f);
    const SurfacePoint sp = mesh.surface_at(ray, *hit);
    EXPECT_FLOAT_EQ(sp.p.x, 0.25f);
    EXPECT_FLOAT_EQ(sp.p.y, 0.5f);
    EXPECT_FLOAT_EQ(sp.p.z, 0);
    EXPECT_EQ(sp.normal, (Normal3{0, 0, 1}));  // from the winding, not towards the ray
    EXPECT_EQ(sp.shading_normal, sp.normal);   // no vertex normals: flat
    // uv = 0.5 (0,0) + 0.25 (2,2) + 0.25 (0,2) = (0.5, 1).
    EXPECT_FLOAT_EQ(sp.uv.x, 0.5f);
    EXPECT_FLOAT_EQ(sp.uv.y, 1.0f);
}

TEST(TriangleMesh, WithoutUvsTheUvIsBarycentric) {
    const TriangleMesh mesh = build(quad_arrays());
    const Ray ray{{0.75f, 0.25f, -1}, {0, 0, 1}};  // from below: two-sided
    const auto hit = mesh.intersect(ray, {});
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->part, 0u);
    EXPECT_FLOAT_EQ(hit->t, 1);
    // 0.25 v0 + 0.5 v1 + 0.25 v2 = (0.75, 0.25).
    const SurfacePoint sp = mesh.surface_at(ray, *hit);
    EXPECT_FLOAT_EQ(sp.uv.x, 0.5f);
    EXPECT_FLOAT_EQ(sp.uv.y, 0.25f);
    EXPECT_EQ(sp.normal, (Normal3{0, 0, 1}));
}

TEST(TriangleMesh, MissesOutsideAndBeyondTheRange) {
    const TriangleMesh mesh = build(quad_arrays());
    EXPECT_FALSE(mesh.intersect({{1.5f, 0.5f, 1}, {0, 0, -1}}, {}));
    EXPECT_FALSE(mesh.intersect({{0.5f, 0.5f, 1}, {0, 0, -1}}, {0, 0.5f}));
    EXPECT_FALSE(mesh.intersect({{0.5f, 0.5f, 1}, {0, 0, 1}}, {}));
    EXPECT_TRUE(mesh.occluded({{0.5f, 0.5f, 1}, {0, 0, -1}}, {0, 1}));
    EXPECT_FALSE(mesh.occluded({{0.5f, 0.5f, 1}, {0, 0, -1}}, {0, 0.99f}));
}

TEST(TriangleMesh, ShadingNormalInterpolatesVertexNormals) {
    MeshData arrays = quad_arrays();
    // Unnormalised on purpose: build_mesh normalises them.
    arrays.normals = {{0, 0, 2}, {1, 0, 1}, {1, 0, 1}, {0, 0, 1}};
    const TriangleMesh mesh = build(arrays);
    const Ray ray{{0.5f, 0.25f, 1}, {0, 0, -1}};
    const auto hit = mesh.intersect(ray, {});
    ASSERT_TRUE(hit);
    const SurfacePoint sp = mesh.surface_at(ray, *hit);
    // Triangle 0: 0.5 v0 + 0.25 v1 + 0.25 v2; n = 0.5 (0,0,1) + 0.5 (0.7071, 0, 0.7071)
    // = (0.35355, 0, 0.85355), normalised (0.38268, 0, 0.92388): 22.5 degrees from +z.
    EXPECT_NEAR(sp.shading_normal.x, 0.38268f, 1e-5f);
    EXPECT_NEAR(sp.shading_normal.y, 0, 1e-6f);
    EXPECT_NEAR(sp.shading_normal.z, 0.92388f, 1e-5f);
    EXPECT_EQ(sp.normal, (Normal3{0, 0, 1}));
}

TEST(TriangleMesh, ShadingNormalsAgainstTheWindingAreTurnedOver) {
    MeshData arrays = quad_arrays();
    arrays.normals.assign(4, Normal3{0, 0.6f, -0.8f});
    const TriangleMesh mesh = build(arrays);
    const Ray ray{{0.5f, 0.25f, 1}, {0, 0, -1}};
    const SurfacePoint sp = mesh.surface_at(ray, *mesh.intersect(ray, {}));
    EXPECT_NEAR(sp.shading_normal.y, -0.6f, 1e-6f);
    EXPECT_NEAR(sp.shading_normal.z, 0.8f, 1e-6f);
}

TEST(TriangleMesh, ZeroOrInPlaneNormalsFallBackToTheGeometricOne) {
    MeshData arrays = quad_arrays();
    arrays.normals = {{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {0, 0, 0}};
    const TriangleMesh mesh = build(arrays);
    const Ray ray{{0.1f, 0.9f, 1}, {0, 0, -1}};  // triangle 1: vertices 0, 2, 3
    const SurfacePoint sp = mesh.surface_at(ray, *mesh.intersect(ray, {}));
    EXPECT_EQ(sp.shading_normal, (Normal3{0, 0, 1}));
}

TEST(TriangleMesh, DegenerateTrianglesAreDroppedAndCounted) {
    MeshData arrays = quad_arrays();
    arrays.positions.push_back({2, 0, 0});
    arrays.triangles.push_back({0, 0, 1});  // repeated index
    arrays.triangles.push_back({0, 1, 4});  // collinear
    arrays.triangles.push_back({3, 2, 1});
    const MeshBuild built = build_mesh(arrays);
    ASSERT_TRUE(built.mesh) << built.error;
    EXPECT_EQ(built.degenerate_dropped, 2u);
    ASSERT_EQ(built.mesh->triangles.size(), 3u);
    EXPECT_EQ(built.mesh->triangles[2], (std::array<std::uint32_t, 3>{3, 2, 1}));
}

TEST(TriangleMesh, BadArraysAreClearErrors) {
    MeshData out_of_range = quad_arrays();
    out_of_range.triangles.push_back({0, 1, 7});
    EXPECT_EQ(build_mesh(out_of_range).error, "triangle 2 uses vertex 7 but there are 4 vertices");

    MeshData nan = quad_arrays();
    nan.positions[2].y = std::nanf("");
    EXPECT_NE(build_mesh(nan).error.find("vertex 2 has a coordinate that is not finite"),
              std::string::npos);

    MeshData huge = quad_arrays();
    huge.positions[1].x = 1e30f;
    EXPECT_FALSE(build_mesh(huge).mesh);

    MeshData normals = quad_arrays();
    normals.normals = {{0, 0, 1}};
    EXPECT_EQ(build_mesh(normals).error, "mesh has 1 normals for 4 vertices");

    MeshData uvs = quad_arrays();
    uvs.uvs.assign(4, Point2{0, INFINITY});
    EXPECT_NE(build_mesh(uvs).error.find("uv 0"), std::string::npos);

    EXPECT_EQ(build_mesh(MeshData{}).error, "mesh has no triangles");
    MeshData flat;
    flat.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
    flat.triangles = {{0, 1, 2}};
    EXPECT_EQ(build_mesh(flat).error,
              "mesh has no triangles left after dropping 1 degenerate ones");
}

// An icosphere-like closed mesh: a subdivided octahedron pushed onto the unit sphere.
MeshData sphere_mesh(int subdivisions) {
    MeshData m;
    m.positions = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    m.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                   {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    for (int s = 0; s < subdivisions; ++s) {
        std::vector<std::array<std::uint32_t, 3>> next;
        for (const auto& t : m.triangles) {
            std::uint32_t mid[3];
            for (int k = 0; k < 3; ++k) {
                const Point3 a = m.positions[t[k]], b = m.positions[t[(k + 1) % 3]];
                const Vector3 c = normalize(to_vector(a) + to_vector(b));
                mid[k] = std::uint32_t(m.positions.size());
                m.positions.push_back(to_point(c));  // duplicated per triangle: welded by position
            }
            next.push_back({t[0], mid[0], mid[2]});
            next.push_back({mid[0], t[1], mid[1]});
            next.push_back({mid[2], mid[1], t[2]});
            next.push_back({mid[0], mid[1], mid[2]});
        }
        m.triangles.assign(next.begin(), next.end());
    }
    return m;
}

TEST(TriangleMesh, SmoothNormalsOfASphereMatchItsRadii) {
    MeshData arrays = sphere_mesh(3);
    compute_vertex_normals(arrays, 60);
    const TriangleMesh mesh = build(arrays);
    for (std::size_t i = 0; i < mesh.data->positions.size(); ++i) {
        const Vector3 radial = normalize(to_vector(mesh.data->positions[i]));
        ASSERT_GT(dot(radial, to_vector(mesh.data->normals[i])), 0.995f) << "vertex " << i;
    }
    // Smooth shading varies across a triangle; the flat normal does not.
    const Ray ray{{0.3f, 0.2f, 5}, {0, 0, -1}};
    const SurfacePoint sp = mesh.surface_at(ray, *mesh.intersect(ray, {}));
    const Vector3 radial = normalize(to_vector(sp.p));
    EXPECT_GT(dot(radial, to_vector(sp.shading_normal)), dot(radial, to_vector(sp.normal)));
}

TEST(TriangleMesh, PropertiesOfAClosedMesh) {
    MeshData arrays = sphere_mesh(3);
    compute_vertex_normals(arrays, 60);
    const TriangleMesh mesh = build(arrays);
    // Distance to the triangle's plane through the hit: zero on the surface. The plane is found
    // by the nearest triangle centroid, which suffices for points on the mesh.
    const auto distance_to_surface = [&](Point3 p) {
        float best = kInfinity;
        for (const auto& t : mesh.data->triangles) {
            const Point3 a = mesh.data->positions[t[0]], b = mesh.data->positions[t[1]],
                         c = mesh.data->positions[t[2]];
            const Vector3 n = normalize(cross(b - a, c - a));
            const float d = std::abs(dot(n, p - a));
            const Point3 centroid = to_point((to_vector(a) + to_vector(b) + to_vector(c)) / 3);
            if (distance(centroid, p) < 0.3f) best = std::min(best, d);
        }
        return best;
    };
    testing::PropertyOptions options;
    options.rays = 500;
    options.min_hits = 100;
    options.convex = false;  // meshes in general are not, and the checks must not assume it
    testing::expect_shape_properties(mesh, distance_to_surface,
                                     testing::RandomRays({0, 0, 0}, 1.2f), options);
}

// A mesh's counterpart of "the normal is the gradient": the geometric normal is the unit normal
// of the triangle hit (hit.part), by its winding, outwards on this closed mesh; the smooth
// shading normal stays on its side.
TEST(TriangleMesh, NormalIsTheFaceNormalOfTheTriangleHit) {
    MeshData arrays = sphere_mesh(3);
    compute_vertex_normals(arrays, 60);
    const TriangleMesh mesh = build(arrays);
    testing::RandomRays rays({0, 0, 0}, 1.2f, 5);
    int hits = 0;
    for (int i = 0; i < 500; ++i) {
        const Ray ray = rays.next();
        const auto hit = mesh.intersect(ray, {});
        if (!hit) continue;
        ++hits;
        const auto& t = mesh.data->triangles[hit->part];
        const Point3 a = mesh.data->positions[t[0]], b = mesh.data->positions[t[1]],
                     c = mesh.data->positions[t[2]];
        const Vector3 face = normalize(cross(b - a, c - a));
        const SurfacePoint sp = mesh.surface_at(ray, *hit);
        EXPECT_GT(dot(sp.normal, face), 0.99999f) << "ray " << i;
        EXPECT_GT(dot(face, to_vector(sp.p)), 0) << "ray " << i;  // outwards
        EXPECT_GT(dot(sp.shading_normal, face), 0) << "ray " << i;
    }
    EXPECT_GT(hits, 100);
}

TEST(TriangleMesh, ClosedMeshesAreSolidsAndOpenOnesAreNot) {
    EXPECT_TRUE(is_closed_surface(*build(sphere_mesh(2)).data));
    EXPECT_FALSE(is_closed_surface(*build(quad_arrays()).data));
    // A closed mesh with one triangle turned over is not consistently oriented.
    MeshData flipped = sphere_mesh(2);
    std::swap(flipped.triangles[0][1], flipped.triangles[0][2]);
    EXPECT_FALSE(is_closed_surface(*build(flipped).data));
    // A closed mesh whose vertices are split (as files do for normals) is still closed.
    MeshData split = sphere_mesh(2);
    const auto first = split.triangles[0];
    for (int k = 0; k < 3; ++k) {
        split.positions.push_back(split.positions[first[k]]);
        split.triangles[0][k] = std::uint32_t(split.positions.size() - 1);
    }
    EXPECT_TRUE(is_closed_surface(*build(split).data));
}

TEST(TriangleMesh, PropertiesOfANonConvexMesh) {
    // A zig-zag roof: non-convex, so leaving rays may legitimately hit it again further away.
    MeshData arrays;
    for (int i = 0; i <= 8; ++i) {
        const float x = float(i) * 0.25f - 1, y = (i % 2) * 0.5f;
        arrays.positions.push_back({x, y, -1});
        arrays.positions.push_back({x, y, 1});
    }
    for (std::uint32_t i = 0; i < 8; ++i) {
        arrays.triangles.push_back({2 * i, 2 * i + 1, 2 * i + 2});
        arrays.triangles.push_back({2 * i + 2, 2 * i + 1, 2 * i + 3});
    }
    const TriangleMesh mesh = build(arrays);
    const auto distance_to_surface = [](Point3 p) {
        // The roof's height at x: a triangle wave of period 0.5 between 0 and 0.5.
        const float s = (p.x + 1) / 0.25f;
        const float f = s - 2 * std::floor(s / 2);
        const float height = 0.5f * (f <= 1 ? f : 2 - f);
        return (p.y - height) / std::sqrt(5.0f);  // the faces rise 2 in 1: |grad| = sqrt(5)
    };
    testing::PropertyOptions options;
    options.surface_tolerance = 2e-6f;
    // Each face is a piece of the function's zero set, and its normal the function's gradient
    // there; hits within the difference step of a ridge or valley see two faces.
    options.normal_matches_gradient = true;
    options.gradient_mismatch_fraction = 0.02f;
    testing::expect_shape_properties(mesh, distance_to_surface,
                                     testing::RandomRays({0, 0.25f, 0}, 1), options);
}

}  // namespace
}  // namespace glint
