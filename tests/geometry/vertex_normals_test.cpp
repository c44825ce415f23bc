// Crease-angle vertex normals on a cube, a fan with a fold, and across uv seams.
#include "glint/geometry/vertex_normals.h"

#include <gtest/gtest.h>

#include <cmath>

#include "glint/math/constants.h"

namespace glint {
namespace {

// The unit cube, 8 shared vertices, 12 triangles wound outwards.
MeshData cube() {
    MeshData m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                   {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    const std::uint32_t quads[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                       {2, 3, 7, 6}, {1, 2, 6, 5}, {0, 4, 7, 3}};
    for (const auto& q : quads) {
        m.triangles.push_back({q[0], q[1], q[2]});
        m.triangles.push_back({q[0], q[2], q[3]});
    }
    return m;
}

bool is_axis(Normal3 n) {
    const float a = std::abs(n.x) + std::abs(n.y) + std::abs(n.z);
    return std::abs(a - 1) < 1e-6f &&
           (std::abs(n.x) == 1 || std::abs(n.y) == 1 || std::abs(n.z) == 1);
}

TEST(VertexNormals, CubeBelowTheCreaseAngleKeepsItsFacesFlat) {
    MeshData m = cube();
    compute_vertex_normals(m, 30);
    // Each corner splits into one vertex per face that meets there: 8 x 3.
    EXPECT_EQ(m.positions.size(), 24u);
    ASSERT_EQ(m.normals.size(), 24u);
    for (const Normal3& n : m.normals) EXPECT_TRUE(is_axis(n));
    // Every triangle's corners carry its face normal.
    for (const auto& t : m.triangles) {
        const Vector3 face = normalize(
            cross(m.positions[t[1]] - m.positions[t[0]], m.positions[t[2]] - m.positions[t[0]]));
        for (const std::uint32_t v : t) EXPECT_NEAR(dot(face, to_vector(m.normals[v])), 1, 1e-6f);
    }
}

TEST(VertexNormals, CubeAboveTheCreaseAngleIsSmoothWithAngleWeights) {
    MeshData m = cube();
    compute_vertex_normals(m, 100);
    EXPECT_EQ(m.positions.size(), 8u);
    // The faces meet a corner with 90 degrees in all, however they are triangulated, so the
    // angle-weighted normal is the diagonal: (1,1,1)/sqrt(3) = 0.57735 at (1,1,1).
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
        const Vector3 expected = normalize(m.positions[i] - Point3{0.5f, 0.5f, 0.5f});
        EXPECT_NEAR(m.normals[i].x, expected.x, 1e-6f);
        EXPECT_NEAR(m.normals[i].y, expected.y, 1e-6f);
        EXPECT_NEAR(m.normals[i].z, expected.z, 1e-6f);
        EXPECT_NEAR(std::abs(m.normals[i].x), 0.57735f, 1e-5f);
    }
}

TEST(VertexNormals, AFoldSplitsOnlyAtTheCrease) {
    // Two quads sharing the edge x = 0: one flat (normal +z), one tilted up by 40 degrees.
    MeshData m;
    const float c = std::cos(radians(40.0f)), s = std::sin(radians(40.0f));
    m.positions = {{-1, 0, 0}, {0, 0, 0}, {0, 1, 0}, {-1, 1, 0}, {c, 0, s}, {c, 1, s}};
    m.triangles = {{0, 1, 2}, {0, 2, 3}, {1, 4, 5}, {1, 5, 2}};
    MeshData sharp = m;
    compute_vertex_normals(sharp, 30);
    EXPECT_EQ(sharp.positions.size(), 8u);  // the two shared vertices are split
    MeshData smooth = m;
    compute_vertex_normals(smooth, 45);
    EXPECT_EQ(smooth.positions.size(), 6u);
    // At vertex 1 the flat side meets it with 90 degrees (one triangle, 45 + another 45), the
    // tilted side with 90: the normal is halfway, 20 degrees from +z towards -x.
    const Normal3 n = smooth.normals[1];
    EXPECT_NEAR(std::acos(n.z) * 180 / 3.14159265f, 20, 1e-3f);
    EXPECT_LT(n.x, 0);
}

TEST(VertexNormals, UvSeamsDoNotSplitTheShading) {
    // The fold's shared edge, but with the vertices duplicated for different uvs.
    MeshData m;
    m.positions = {{-1, 0, 0}, {0, 0, 0}, {0, 1, 0}, {0, 0, 0}, {0, 1, 0}, {1, 0, 0.2f}};
    m.uvs = {{0, 0}, {0.5f, 0}, {0.5f, 1}, {0.6f, 0}, {0.6f, 1}, {1, 0}};
    m.triangles = {{0, 1, 2}, {3, 5, 4}};
    compute_vertex_normals(m, 60);
    ASSERT_EQ(m.positions.size(), 6u);
    EXPECT_EQ(m.normals[1], m.normals[3]);
    EXPECT_EQ(m.normals[2], m.normals[4]);
    EXPECT_EQ(m.uvs[3], (Point2{0.6f, 0}));
}

TEST(VertexNormals, ZeroAngleIsFlat) {
    MeshData m = cube();
    compute_vertex_normals(m, 0);
    for (const Normal3& n : m.normals) EXPECT_TRUE(is_axis(n));
}

}  // namespace
}  // namespace glint
