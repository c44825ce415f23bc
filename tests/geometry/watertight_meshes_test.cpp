// Watertightness of the triangle test (Woop, Benthin and Wald 2013): rays aimed exactly at the
// shared edges and vertices of closed meshes, from outside and from inside, must all stop there.
// The meshes: an icosphere, a box of two triangles a face, a bipyramid whose apexes are fans of a
// thousand slivers, and the Stanford bunny (tests/data/meshes/bunny_npm.obj); and two Triangle
// shapes that share an edge.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "glint/accel/mesh_bvh.h"
#include "glint/geometry/triangle.h"
#include "glint/geometry/triangle_mesh.h"

namespace glint {
namespace {

// A mesh as plain arrays, with the triangles around each edge and each vertex.
struct Solid {
    const char* name;
    MeshData arrays;
    Point3 center;               // inside, when the mesh is a convex solid
    std::vector<Point3> inside;  // points known to be inside
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::uint32_t>> edge_faces;
    std::vector<std::vector<std::uint32_t>> vertex_faces;
};

void index_faces(Solid& s) {
    s.vertex_faces.assign(s.arrays.positions.size(), {});
    for (std::uint32_t f = 0; f < s.arrays.triangles.size(); ++f) {
        const auto& t = s.arrays.triangles[f];
        for (std::size_t k = 0; k < 3; ++k) {
            const std::uint32_t a = t[k], b = t[(k + 1) % 3];
            s.edge_faces[{std::min(a, b), std::max(a, b)}].push_back(f);
            s.vertex_faces[a].push_back(f);
        }
    }
}

// The icosahedron, each triangle split in four `levels` times, on the unit sphere.
Solid icosphere(int levels) {
    Solid s{"icosphere"};
    const float g = (1 + std::sqrt(5.0f)) / 2;
    auto& p = s.arrays.positions;
    p = {{-1, g, 0},  {1, g, 0},  {-1, -g, 0}, {1, -g, 0}, {0, -1, g},  {0, 1, g},
         {0, -1, -g}, {0, 1, -g}, {g, 0, -1},  {g, 0, 1},  {-g, 0, -1}, {-g, 0, 1}};
    s.arrays.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                          {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                          {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                          {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
    for (auto& v : p) v = to_point(normalize(to_vector(v)));
    for (int level = 0; level < levels; ++level) {
        std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> middle;
        const auto mid = [&](std::uint32_t a, std::uint32_t b) {
            const auto [it, fresh] =
                middle.try_emplace({std::min(a, b), std::max(a, b)}, std::uint32_t(p.size()));
            if (fresh) p.push_back(to_point(normalize(to_vector(p[a]) + to_vector(p[b]))));
            return it->second;
        };
        LargeVector<std::array<std::uint32_t, 3>> finer;
        for (const auto& [a, b, c] : s.arrays.triangles) {
            const std::uint32_t ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
            finer.insert(finer.end(), {{a, ab, ca}, {b, bc, ab}, {c, ca, bc}, {ab, bc, ca}});
        }
        s.arrays.triangles = std::move(finer);
    }
    s.center = {0, 0, 0};
    return s;
}

// An axis-aligned box with two triangles a face, at coordinates that are not round numbers.
Solid box() {
    Solid s{"box"};
    const Point3 lo{-1.3f, -0.7f, -1.1f}, hi{0.9f, 1.3f, 0.7f};
    for (int i = 0; i < 8; ++i) {
        s.arrays.positions.push_back(
            {i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z});
    }
    // Each face's corners counter-clockwise seen from outside, split along one diagonal.
    const std::uint32_t faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                       {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& f : faces) {
        s.arrays.triangles.push_back({f[0], f[1], f[2]});
        s.arrays.triangles.push_back({f[0], f[2], f[3]});
    }
    s.center = {-0.2f, 0.3f, -0.2f};
    return s;
}

// Two cones on a shared rim of n vertices: each apex is a fan of n long, thin triangles.
Solid bipyramid(std::uint32_t n) {
    Solid s{"bipyramid"};
    auto& p = s.arrays.positions;
    p = {{0.1f, 1.2f, -0.05f}, {0.1f, -1.1f, -0.05f}};  // apexes
    for (std::uint32_t i = 0; i < n; ++i) {
        const double a = 2 * std::numbers::pi * i / n;
        p.push_back({float(std::cos(a)), 0.05f, float(std::sin(a))});
    }
    for (std::uint32_t i = 0; i < n; ++i) {
        const std::uint32_t r = 2 + i, next = 2 + (i + 1) % n;
        s.arrays.triangles.push_back({0, next, r});
        s.arrays.triangles.push_back({1, r, next});
    }
    s.center = {0.1f, 0.05f, -0.05f};
    return s;
}

// The positions and triangles of an OBJ file of triangles ("v x y z", "f a b c", 1-based).
MeshData read_obj(const std::filesystem::path& file) {
    MeshData m;
    std::ifstream in(file);
    EXPECT_TRUE(in) << file;
    for (std::string line; std::getline(in, line);) {
        std::istringstream fields(line);
        std::string key;
        fields >> key;
        if (key == "v") {
            Point3 v;
            fields >> v.x >> v.y >> v.z;
            m.positions.push_back(v);
        } else if (key == "f") {
            std::array<std::uint32_t, 3> t{};
            fields >> t[0] >> t[1] >> t[2];
            for (auto& i : t) --i;
            m.triangles.push_back(t);
        }
    }
    return m;
}

// The generalised winding number of the closed mesh about p (Jacobson et al. 2013): +-1 inside
// (the sign is the orientation's), 0 outside, from the triangles' solid angles (Van Oosterom and
// Strackee 1983).
double winding_number(const MeshData& m, Point3 p) {
    double sum = 0;
    for (const auto& t : m.triangles) {
        std::array<std::array<double, 3>, 3> r;
        double len[3];
        for (int k = 0; k < 3; ++k) {
            const Point3 v = m.positions[t[std::size_t(k)]];
            r[k] = {double(v.x) - p.x, double(v.y) - p.y, double(v.z) - p.z};
            len[k] = std::sqrt(r[k][0] * r[k][0] + r[k][1] * r[k][1] + r[k][2] * r[k][2]);
        }
        const auto dot3 = [](const auto& x, const auto& y) {
            return x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
        };
        const auto& [a, b, c] = r;
        const double triple = a[0] * (b[1] * c[2] - b[2] * c[1]) -
                              a[1] * (b[0] * c[2] - b[2] * c[0]) +
                              a[2] * (b[0] * c[1] - b[1] * c[0]);
        const double below = len[0] * len[1] * len[2] + dot3(a, b) * len[2] + dot3(b, c) * len[0] +
                             dot3(c, a) * len[1];
        sum += 2 * std::atan2(triple, below);
    }
    return sum / (4 * std::numbers::pi);
}

Solid bunny() {
    Solid s{"bunny_npm"};
    s.arrays =
        read_obj(std::filesystem::path(GLINT_SOURCE_DIR) / "tests/data/meshes/bunny_npm.obj");
    Bounds3 b;
    for (const Point3 p : s.arrays.positions) b = merge(b, p);
    s.center = b.center();
    // Interior points: random points of the bounds whose winding number is +-1.
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(0, 1);
    while (s.inside.size() < 16) {
        const Vector3 d = b.diagonal();
        const Point3 p = b.min + Vector3{u(rng) * d.x, u(rng) * d.y, u(rng) * d.z};
        if (std::abs(std::abs(winding_number(s.arrays, p)) - 1) < 1e-3) s.inside.push_back(p);
    }
    return s;
}

struct Tally {
    long rays = 0;     // rays that cross the surface at their target, all of which must hit
    long grazing = 0;  // rays that only graze it there (skipped: they may rightly miss)
    long misses = 0;
};

// The cosine of the steepest angle at which a ray along d meets the triangles `faces` at a point
// they share, when it meets them all from the same side and none nearly edge-on (0.01, about
// half a degree, off their planes); 0 otherwise. At a silhouette edge, for one, both triangles
// lie on the same side of it as seen along the ray, which may rightly pass just outside both.
float crossing_cosine(const MeshData& m, const std::vector<std::uint32_t>& faces, Vector3 d) {
    int front = 0, back = 0;
    float least = 1;
    for (const std::uint32_t f : faces) {
        const auto& t = m.triangles[f];
        const Point3 a = m.positions[t[0]], b = m.positions[t[1]], c = m.positions[t[2]];
        const float cosine = dot(normalize(cross(b - a, c - a)), d);
        front += cosine < -0.01f;
        back += cosine > 0.01f;
        least = std::min(least, std::abs(cosine));
    }
    return front == int(faces.size()) || back == int(faces.size()) ? least : 0;
}

// Shoots from `origin` exactly at `target`, a point of the triangles `faces`: a ray that crosses
// the surface there must stop there or before. "There" allows for the rounding of the target and
// of the direction (about 1e-6 of the size across the ray), stretched along the ray by 1 / cos.
void shoot(const Solid& s, const TriangleMesh& mesh, float size, Point3 origin, Point3 target,
           const std::vector<std::uint32_t>& faces, Tally& tally) {
    const Ray ray{origin, normalize(target - origin)};
    const float cosine = crossing_cosine(s.arrays, faces, ray.direction);
    if (cosine == 0) {
        ++tally.grazing;
        return;
    }
    ++tally.rays;
    const float dist = distance(origin, target);
    const float reach = dist + 1e-5f * (dist + size) / cosine;
    const auto hit = mesh.intersect(ray, {});
    if (hit && hit->t <= reach && mesh.occluded(ray, {0, reach})) return;
    if (++tally.misses <= 5) {
        // Brute force tells whether the triangles or the BVH let the ray through.
        bool any = false;
        for (std::uint32_t k = 0; k < s.arrays.triangles.size(); ++k) {
            any = any || intersect_triangle(*mesh.data, k, ray, {0, reach}).has_value();
        }
        ADD_FAILURE() << s.name << ": the ray from (" << origin.x << ", " << origin.y << ", "
                      << origin.z << ") at (" << target.x << ", " << target.y << ", " << target.z
                      << ") slips through (nearest hit at t = " << (hit ? hit->t : kInfinity)
                      << ", the target at " << dist << "); brute force over the triangles "
                      << (any ? "hits" : "misses too");
    }
}

// Rays exactly at every edge (the midpoint and three points a + s (b - a)) and every vertex, from
// random points outside the bounding sphere on the target's side, and from inside.
Tally shoot_at_edges_and_vertices(const Solid& s, int rays_per_vertex = 2) {
    const MeshBuild built = build_mesh(s.arrays);
    EXPECT_TRUE(built.mesh) << built.error;
    EXPECT_TRUE(is_closed_surface(*built.mesh)) << s.name;
    EXPECT_EQ(built.degenerate_dropped, 0u);
    // Through the mesh's own BVH, as the renderer traces it: its leaves test four triangles at
    // once.
    const TriangleMesh mesh{built.mesh, std::make_shared<const MeshBvh>(built.mesh)};
    float radius = 0;
    for (const Point3 p : s.arrays.positions) radius = std::max(radius, distance(p, s.center));
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(-1, 1);
    const auto unit = [&] {
        for (;;) {
            const Vector3 v{u(rng), u(rng), u(rng)};
            if (const float l = length(v); l > 0.1f && l <= 1) return v / l;
        }
    };
    std::uniform_int_distribution<std::size_t> pick(0, s.inside.size() - 1);
    const auto outside = [&](Point3 target) {
        Vector3 away = unit();
        if (dot(away, target - s.center) < 0) away = -away;
        return s.center + away * (2 * radius);
    };
    const auto inside = [&] {
        return s.inside.empty() ? s.center + unit() * (0.3f * radius * u(rng))
                                : s.inside[pick(rng)];
    };
    Tally tally;
    for (const auto& [edge, faces] : s.edge_faces) {
        EXPECT_EQ(faces.size(), 2u) << s.name << " is closed";
        const Point3 a = s.arrays.positions[edge.first], b = s.arrays.positions[edge.second];
        for (int i = 0; i < 5; ++i) {
            const float along = i == 0 ? 0.5f : 0.5f + 0.49f * u(rng);
            const Point3 target = a + (b - a) * along;
            shoot(s, mesh, radius, i < 4 ? outside(target) : inside(), target, faces, tally);
        }
    }
    for (std::size_t v = 0; v < s.vertex_faces.size(); ++v) {
        const Point3 target = s.arrays.positions[v];
        for (int i = 0; i < rays_per_vertex; ++i) {
            shoot(s, mesh, radius, outside(target), target, s.vertex_faces[v], tally);
            shoot(s, mesh, radius, inside(), target, s.vertex_faces[v], tally);
        }
    }
    std::printf(
        "[ watertight ] %s (%zu triangles): %ld rays exactly through edges and vertices, %ld "
        "missed (%ld grazing rays skipped)\n",
        s.name, s.arrays.triangles.size(), tally.rays, tally.misses, tally.grazing);
    EXPECT_EQ(tally.misses, 0) << s.name;
    return tally;
}

TEST(WatertightTriangle, NoRaySlipsThroughAnIcosphere) {
    Solid s = icosphere(3);
    index_faces(s);
    const Tally t = shoot_at_edges_and_vertices(s);
    EXPECT_GT(t.rays, 9000);
}

TEST(WatertightTriangle, NoRaySlipsThroughABoxOfTwoTrianglesAFace) {
    Solid s = box();
    index_faces(s);
    EXPECT_GT(shoot_at_edges_and_vertices(s, 400).rays, 2000);
    // Rays along the axes onto the faces' diagonals: the shear is then no shear at all.
    const TriangleMesh mesh{build_mesh(s.arrays).mesh};
    std::mt19937 rng(8);
    std::uniform_real_distribution<float> along(0, 1);
    for (int i = 0; i < 2000; ++i) {
        const auto& t = s.arrays.triangles[2 * (std::size_t(i) % 6)];  // t[0] -> t[2]: a diagonal
        const Point3 target = s.arrays.positions[t[0]] +
                              (s.arrays.positions[t[2]] - s.arrays.positions[t[0]]) * along(rng);
        const Vector3 n = normalize(cross(s.arrays.positions[t[1]] - s.arrays.positions[t[0]],
                                          s.arrays.positions[t[2]] - s.arrays.positions[t[0]]));
        // From outside, 5 away, and from inside, 0.5 away (every half-extent is 0.9 or more).
        const auto in = mesh.intersect({target + n * 5, -n}, {});
        const auto out = mesh.intersect({target - n * 0.5f, n}, {});
        ASSERT_TRUE(in && out) << "diagonal ray " << i;
        EXPECT_NEAR(in->t, 5, 1e-5f) << "diagonal ray " << i;
        EXPECT_NEAR(out->t, 0.5f, 1e-5f) << "diagonal ray " << i;
    }
}

TEST(WatertightTriangle, NoRaySlipsThroughAFanOfAThousandTriangles) {
    Solid s = bipyramid(1000);
    index_faces(s);
    EXPECT_GT(shoot_at_edges_and_vertices(s).rays, 10000);
    // The apexes, where a thousand slivers meet: from above and below within their cones.
    const TriangleMesh mesh{build_mesh(s.arrays).mesh};
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> u(-1, 1);
    Tally apex;
    for (int i = 0; i < 4000; ++i) {
        const std::uint32_t v = i % 2;
        const Point3 target = s.arrays.positions[v];
        const Vector3 away{0.7f * u(rng), v == 0 ? 1.0f : -1.0f, 0.7f * u(rng)};
        shoot(s, mesh, 1, target + normalize(away) * 3, target, s.vertex_faces[v], apex);
        shoot(s, mesh, 1, s.center + Vector3{u(rng), u(rng), u(rng)} * 0.2f, target,
              s.vertex_faces[v], apex);
    }
    std::printf("[ watertight ] bipyramid apexes: %ld rays, %ld missed\n", apex.rays, apex.misses);
    EXPECT_EQ(apex.misses, 0);
    EXPECT_GT(apex.rays, 6000);
}

TEST(WatertightTriangle, NoRaySlipsThroughTheBunny) {
    Solid s = bunny();
    ASSERT_EQ(s.arrays.triangles.size(), 3674u);
    index_faces(s);
    const Tally t = shoot_at_edges_and_vertices(s);
    EXPECT_GT(t.rays, 25000);
}

// The single-triangle path: two Triangle shapes sharing the diagonal of a skew quad, from the
// directions in which the diagonal is not a silhouette.
TEST(WatertightTriangle, NoRaySlipsBetweenTwoTriangleShapes) {
    const Point3 a{-0.31f, 0.17f, 0.05f}, b{1.13f, -0.23f, 0.41f}, c{0.97f, 1.19f, -0.29f},
        d{-0.43f, 0.89f, 0.11f};
    const Triangle first{{a, b, c}}, second{{a, c, d}};
    const Vector3 n1 = normalize(cross(b - a, c - a)), n2 = normalize(cross(c - a, d - a));
    std::mt19937 rng(10);
    std::uniform_real_distribution<float> u(-1, 1);
    int rays = 0, misses = 0;
    for (int i = 0; i < 20000; ++i) {
        const Point3 target = a + (c - a) * (0.5f + 0.49f * u(rng));
        const Point3 origin = target + Vector3{u(rng), u(rng), u(rng)} * 3;
        const Ray ray{origin, normalize(target - origin)};
        const float c1 = dot(n1, ray.direction), c2 = dot(n2, ray.direction);
        if (!((c1 < -0.01f && c2 < -0.01f) || (c1 > 0.01f && c2 > 0.01f))) continue;
        ++rays;
        misses += !first.intersect(ray, {}) && !second.intersect(ray, {});
    }
    EXPECT_GT(rays, 15000);
    EXPECT_EQ(misses, 0);
}

}  // namespace
}  // namespace glint
