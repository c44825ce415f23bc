// Every mesh of ../shared/data/meshes (third-party models, kept outside the repository): counts
// against its README, rays through each, and how often Moeller-Trumbore lets a ray slip through
// the shared edges of a closed mesh. Skipped when the folder is absent.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>

#include "glint/accel/mesh_bvh.h"
#include "glint/scene/mesh/model_loader.h"
#include "glint/scene/scene_error.h"

namespace glint {
namespace {

const std::filesystem::path kShared =
    std::filesystem::path(GLINT_SOURCE_DIR) / "../shared/data/meshes";

struct Expected {
    const char* file;
    std::size_t triangles;
    std::size_t vertices;  // as the README counts them; uv seams may add vertices on import
    Bounds3 bounds;
};

// From ../shared/data/meshes/README.md.
const Expected kExpected[] = {
    {"bunny_npm.obj", 3674, 1839, {{-4.959f, -0.003f, -3.730f}, {4.949f, 9.655f, 3.811f}}},
    {"stanford-bunny.obj", 69451, 35947, {{-0.095f, 0.033f, -0.062f}, {0.061f, 0.187f, 0.059f}}},
    {"spot_triangulated.obj", 5856, 2930, {{-0.472f, -0.737f, -0.669f}, {0.472f, 0.954f, 1.049f}}},
    {"teapot_newell.obj", 6320, 3644, {{-3, 0, -2}, {3.434f, 3.15f, 2}}},
    {"teapot_npm.obj", 992, 792, {{-16.07f, -7.875f, -10}, {16.07f, 7.875f, 10}}},
    {"suzanne.obj", 968, 507, {{-3.861f, 0.267f, 3.252f}, {-1.127f, 2.236f, 4.956f}}},
    {"fandisk.obj", 12946, 6475, {{0, 12.61f, -2.68f}, {4.83f, 17.85f, 0}}},
};

Model load_shared(const std::string& name, const ModelOptions& options = {}) {
    try {
        return load_model(kShared / name, options);
    } catch (const SceneError& e) {
        ADD_FAILURE() << format_scene_error(e);
        return {};
    }
}

class SharedMeshes : public ::testing::Test {
protected:
    void SetUp() override {
        if (!std::filesystem::is_directory(kShared)) GTEST_SKIP() << kShared << " is absent";
    }
};

// The number of lines of the file that start with `prefix`.
std::size_t count_lines(const std::filesystem::path& file, const std::string& prefix) {
    std::ifstream in(file);
    std::size_t n = 0;
    for (std::string line; std::getline(in, line);) n += line.starts_with(prefix);
    return n;
}

// The mesh traced whole through its own BVH, as instances are.
TriangleMesh traced_whole(std::shared_ptr<const MeshData> mesh) {
    return {mesh, std::make_shared<const MeshBvh>(mesh)};
}

// The nearest hit over every triangle, without the BVH.
std::optional<ShapeHit> brute_force(const TriangleMesh& mesh, const Ray& ray, Interval range) {
    return TriangleMesh{mesh.data}.intersect(ray, range);
}

TEST_F(SharedMeshes, CountsAndBoundsMatchTheReadme) {
    for (const Expected& e : kExpected) {
        SCOPED_TRACE(e.file);
        EXPECT_EQ(count_lines(kShared / e.file, "v "), e.vertices);
        const Model m = load_shared(e.file);
        ASSERT_EQ(m.parts.size(), 1u);
        const MeshData& mesh = *m.parts[0].mesh;
        EXPECT_EQ(mesh.triangles.size(), e.triangles);
        // Assimp welds vertices at the same position (the teapots repeat theirs at patch
        // seams); uvs split them again.
        if (mesh.uvs.empty()) {
            EXPECT_LE(mesh.positions.size(), e.vertices);
        }
        // The README rounds the bounds to two or three decimals.
        for (int a = 0; a < 3; ++a) {
            EXPECT_NEAR(m.bounds.min[a], e.bounds.min[a], 0.0051f) << "axis " << a;
            EXPECT_NEAR(m.bounds.max[a], e.bounds.max[a], 0.0051f) << "axis " << a;
        }
        EXPECT_TRUE(m.warnings.empty()) << m.warnings.front();
    }
}

// Rays at triangle centroids from outside must hit no further than the centroid; rays beside
// the bounds miss; and the BVH agrees with brute force on random rays, axis-parallel rays and
// rays that start on the surface.
TEST_F(SharedMeshes, RaysHitWhereTheyShouldAndTheBvhMatchesBruteForce) {
    for (const Expected& e : kExpected) {
        SCOPED_TRACE(e.file);
        const Model m = load_shared(e.file);
        ASSERT_FALSE(m.parts.empty());
        const TriangleMesh mesh = traced_whole(m.parts[0].mesh);
        const MeshData& data = *mesh.data;
        const Point3 c = m.bounds.center();
        const float size = length(m.bounds.diagonal());
        std::mt19937 rng(9);
        std::uniform_real_distribution<float> u(-1, 1);
        std::uniform_int_distribution<std::uint32_t> pick(0,
                                                          std::uint32_t(data.triangles.size() - 1));
        const auto random_direction = [&] {
            for (;;) {
                const Vector3 v{u(rng), u(rng), u(rng)};
                if (length(v) > 0.1f && length(v) <= 1) return normalize(v);
            }
        };
        for (int i = 0; i < 300; ++i) {
            const auto& t = data.triangles[pick(rng)];
            const Point3 centroid =
                to_point((to_vector(data.positions[t[0]]) + to_vector(data.positions[t[1]]) +
                          to_vector(data.positions[t[2]])) /
                         3);
            const Point3 origin = centroid + random_direction() * (2 * size);
            const Ray ray{origin, normalize(centroid - origin)};
            const auto hit = mesh.intersect(ray, {});
            ASSERT_TRUE(hit) << "ray " << i;
            ASSERT_LE(hit->t, distance(origin, centroid) + 1e-4f * size) << "ray " << i;

            // Random rays through the bounds, every third along an axis, every third from a
            // point on the surface.
            Point3 o = c + random_direction() * size;
            Vector3 d = normalize(c + random_direction() * (0.3f * size) - o);
            if (i % 3 == 1) d = i % 2 ? Vector3{0, 0, -1} : Vector3{1, 0, 0};
            if (i % 3 == 2) {
                o = hit ? ray.at(hit->t) : o;
                d = random_direction();
            }
            if (i >= 100) continue;  // brute force is slow on the 69k-triangle bunny
            const Ray probe{o, d};
            const auto expected = brute_force(mesh, probe, {});
            const auto got = mesh.intersect(probe, {});
            ASSERT_EQ(bool(expected), bool(got)) << "probe " << i;
            if (expected) {
                ASSERT_EQ(got->t, expected->t) << "probe " << i;
            }
        }
        for (int a = 0; a < 3; ++a) {
            Vector3 d;
            d = a == 0 ? Vector3{1, 0, 0} : a == 1 ? Vector3{0, 1, 0} : Vector3{0, 0, 1};
            EXPECT_FALSE(mesh.intersect({c + Vector3{1, 1, 1} * size - d * (2 * size), d}, {}));
        }
    }
}

// Rays aimed exactly at points of the edges two triangles share, from outside and from random
// directions. A closed mesh must stop every one; Moeller-Trumbore is not watertight, so some slip
// between the two triangles. The rate is reported, not changed (see docs/meshes.md).
TEST_F(SharedMeshes, RaysThroughSharedEdgesOfAClosedMesh) {
    const Model m = load_shared("bunny_npm.obj");
    ASSERT_EQ(m.parts.size(), 1u);
    const TriangleMesh mesh = traced_whole(m.parts[0].mesh);
    const MeshData& data = *mesh.data;
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
    for (const auto& t : data.triangles) {
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = t[std::size_t(k)], b = t[std::size_t((k + 1) % 3)];
            ++edges[{std::min(a, b), std::max(a, b)}];
        }
    }
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(-1, 1);
    const float distance_out = 0.05f * length(m.bounds.diagonal());
    long rays = 0, misses = 0, midpoint_misses = 0;
    for (const auto& [edge, count] : edges) {
        ASSERT_EQ(count, 2) << "bunny_npm is closed: every edge has two triangles";
        const Point3 a = data.positions[edge.first], b = data.positions[edge.second];
        for (int i = 0; i < 4; ++i) {
            // i == 0: the midpoint; then random points along the edge.
            const float s = i == 0 ? 0.5f : 0.5f + 0.45f * u(rng);
            const Point3 target = a + (b - a) * s;
            Vector3 away{u(rng), u(rng), u(rng)};
            if (length(away) < 1e-3f) away = {0, 1, 0};
            const Point3 origin = target + normalize(away) * distance_out;
            const Ray ray{origin, normalize(target - origin)};
            ++rays;
            if (!mesh.intersect(ray, {})) {
                ++misses;
                midpoint_misses += i == 0;
                // The BVH is not to blame: the triangles themselves let the ray through.
                ASSERT_FALSE(brute_force(mesh, ray, {}));
            }
        }
    }
    const double rate = double(misses) / double(rays);
    std::printf(
        "[ watertight ] %ld of %ld rays through shared edges of bunny_npm missed "
        "(%.4f%%; %ld at midpoints)\n",
        misses, rays, 100 * rate, midpoint_misses);
    RecordProperty("edge_rays", int(rays));
    RecordProperty("edge_misses", int(misses));
    // Not a correctness bound but a regression guard, set above the rate measured when this test
    // was written (2.1%).
    EXPECT_LT(rate, 0.04);
}

TEST_F(SharedMeshes, StanfordBunnyLoadTime) {
    const auto start = std::chrono::steady_clock::now();
    const Model m = load_shared("stanford-bunny.obj");
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf(
        "[ timing     ] stanford-bunny.obj (69451 triangles) loaded with its BVH in "
        "%.3f s\n",
        seconds);
    RecordProperty("stanford_bunny_load_ms", int(seconds * 1000));
    EXPECT_EQ(m.parts.size(), 1u);
}

TEST_F(SharedMeshes, CreaseAngleSmoothingOfTheFandisk) {
    ModelOptions options;
    options.crease_angle_degrees = 30;
    const Model m = load_shared("fandisk.obj", options);
    ASSERT_EQ(m.parts.size(), 1u);
    const MeshData& mesh = *m.parts[0].mesh;
    EXPECT_EQ(mesh.triangles.size(), 12946u);
    // The CAD part's sharp creases split vertices; smooth regions do not.
    EXPECT_GT(mesh.positions.size(), 6475u);
    EXPECT_LT(mesh.positions.size(), 2 * 6475u);
    ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
}

}  // namespace
}  // namespace glint
