// The watertight triangle test (Woop, Benthin and Wald 2013) on single triangles: worked hits,
// the range, agreement with an exact solve, degenerate triangles, NaNs and rays parallel to the
// plane. watertight_meshes_test.cpp shoots at the shared edges and vertices of closed meshes.
#include "glint/geometry/watertight_triangle.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>

#include "glint/geometry/triangle.h"

namespace glint {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

// ---------------------------------------------------------------------------------------------
// Worked numbers and the range

TEST(WatertightTriangle, WorkedObliqueHitOnTheFrontSide) {
    // Triangle (0,0,0), (2,0,0), (0,2,0); ray from (1,-1,2) along (0, 0.6, -0.8).
    // Shear: |dz| is largest, so kz = z; dz < 0 swaps x and y: kx = y, ky = x.
    //   sx = 0.6 / -0.8 = -0.75, sy = 0 / -0.8 = 0, sz = 1 / -0.8 = -1.25 (all exact in float).
    // Vertices minus the origin: A = (-1,1,-2), B = (1,1,-2), C = (-1,3,-2); sheared
    // (x', y') = (p.y - sx p.z, p.x - sy p.z): A' = (-0.5,-1), B' = (-0.5,1), C' = (1.5,-1).
    // Edge functions: U = C'x B'y - C'y B'x = 1.5 - 0.5 = 1; V = A'x C'y - A'y C'x = 0.5 + 1.5 = 2;
    // W = B'x A'y - B'y A'x = 0.5 + 0.5 = 1. det = 4 > 0: the front side.
    // u = V / det = 0.5, v = W / det = 0.25; t = sz (U Az + V Bz + W Cz) / det = -1.25 * -8 / 4
    // = 2.5, and indeed (1,-1,2) + 2.5 (0,0.6,-0.8) = (1,0.5,0) = 0.25 v0 + 0.5 v1 + 0.25 v2.
    const RayShear shear({0, 0.6f, -0.8f});
    EXPECT_EQ(shear.kx, 1);
    EXPECT_EQ(shear.ky, 0);
    EXPECT_EQ(shear.kz, 2);
    EXPECT_EQ(shear.sx, -0.75f);
    EXPECT_EQ(shear.sz, -1.25f);
    const Triangle tri{{Point3{0, 0, 0}, Point3{2, 0, 0}, Point3{0, 2, 0}}};
    const Ray ray{{1, -1, 2}, {0, 0.6f, -0.8f}};
    const auto hit = tri.intersect(ray, {});
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->t, 2.5f);
    EXPECT_EQ(hit->u, 0.5f);
    EXPECT_EQ(hit->v, 0.25f);
    EXPECT_EQ(tri.surface_at(ray, *hit).p, (Point3{1, 0.5f, 0}));
}

TEST(WatertightTriangle, WorkedHitOnTheBackSideAlongX) {
    // Triangle (0,0,0), (0,4,0), (0,0,4) in the plane x = 0, front side +x; ray from (-3,1,2)
    // along +x. kz = x, kx = y, ky = z, no swap; sx = sy = 0, sz = 1.
    // A = (3,-1,-2), B = (3,3,-2), C = (3,-1,2): A' = (-1,-2), B' = (3,-2), C' = (-1,2), z = 3.
    // U = (-1)(-2) - (2)(3) = -4; V = (-1)(2) - (-2)(-1) = -4; W = (3)(-2) - (-2)(-1) = -8.
    // det = -16 < 0: the back side, accepted (two-sided). u = -4/-16 = 0.25, v = -8/-16 = 0.5,
    // t = (3 (-4 - 4 - 8)) / -16 = 3: the point (0,1,2) = 0.25 (0,4,0) + 0.5 (0,0,4).
    const Triangle tri{{Point3{0, 0, 0}, Point3{0, 4, 0}, Point3{0, 0, 4}}};
    const auto hit = tri.intersect({{-3, 1, 2}, {1, 0, 0}}, {});
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->t, 3);
    EXPECT_EQ(hit->u, 0.25f);
    EXPECT_EQ(hit->v, 0.5f);
    // The same point from the front (-x: kz = x, swapped, sz = -1) gives U, V, W = 4, 4, 8.
    const auto front = tri.intersect({{3, 1, 2}, {-1, 0, 0}}, {});
    ASSERT_TRUE(front);
    EXPECT_EQ(front->t, 3);
    EXPECT_EQ(front->u, 0.25f);
    EXPECT_EQ(front->v, 0.5f);
}

TEST(WatertightTriangle, WorkedHitOnASlopedTriangle) {
    // The plane x + y + z = 1 through (1,0,0), (0,1,0), (0,0,1); from the origin along
    // (1,1,1)/sqrt(3) the ray meets it at (1,1,1)/3: t = 1/sqrt(3), u = v = 1/3. From (1,1,1)
    // the other way it travels sqrt(3) - 1/sqrt(3) = 2/sqrt(3).
    const Triangle tri{{Point3{1, 0, 0}, Point3{0, 1, 0}, Point3{0, 0, 1}}};
    const Vector3 d = normalize(Vector3{1, 1, 1});
    const auto hit = tri.intersect({{0, 0, 0}, d}, {});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 1 / std::sqrt(3.0), 1e-6);
    EXPECT_NEAR(hit->u, 1 / 3.0, 1e-6);
    EXPECT_NEAR(hit->v, 1 / 3.0, 1e-6);
    const auto back = tri.intersect({{1, 1, 1}, -d}, {});
    ASSERT_TRUE(back);
    EXPECT_NEAR(back->t, 2 / std::sqrt(3.0), 1e-6);
    EXPECT_NEAR(back->u, 1 / 3.0, 1e-6);
}

TEST(WatertightTriangle, TheRangeIsClosedAndRespected) {
    const Triangle tri{{Point3{0, 0, 0}, Point3{2, 0, 0}, Point3{0, 2, 0}}};
    const Ray ray{{0.5f, 0.5f, 3}, {0, 0, -1}};  // t = 3 exactly
    EXPECT_TRUE(tri.intersect(ray, {3, 3}));
    EXPECT_FALSE(tri.intersect(ray, {0, 2.9999998f}));
    EXPECT_FALSE(tri.intersect(ray, {3.0000002f, 10}));
    EXPECT_FALSE(tri.intersect({{0.5f, 0.5f, -3}, {0, 0, -1}}, {}));  // behind the origin
    EXPECT_TRUE(tri.intersect({{0.5f, 0.5f, -3}, {0, 0, -1}}, {-kInfinity, kInfinity}));
}

// Closest-hit searches narrow the range to the nearest t so far, in an order that depends on the
// structure; they agree only if a hit at t is found for every range that contains t, and for no
// other. Rays at shared edges make equal t from two triangles common.
TEST(WatertightTriangle, AHitDoesNotDependOnHowFarTheRangeReaches) {
    std::mt19937 rng(20);
    std::uniform_real_distribution<float> u(-1, 1);
    int hits = 0;
    for (int i = 0; i < 20000; ++i) {
        const float scale = std::pow(10.0f, float(i % 7) - 3);  // 1e-3 to 1e3
        const Point3 v0{u(rng) * scale, u(rng) * scale, u(rng) * scale};
        const Point3 v1{u(rng) * scale, u(rng) * scale, u(rng) * scale};
        const Point3 v2{u(rng) * scale, u(rng) * scale, u(rng) * scale};
        const Point3 origin{u(rng) * 3 * scale, u(rng) * 3 * scale, u(rng) * 3 * scale};
        // Aim at an edge, often enough exactly.
        const Point3 aim = i % 2 ? v0 + (v1 - v0) * (0.5f + 0.5f * u(rng)) : v2;
        if (distance(aim, origin) == 0) continue;
        const Ray ray{origin, normalize(aim - origin)};
        const auto hit = intersect_triangle(v0, v1, v2, ray, {});
        if (!hit) continue;
        ++hits;
        const float t = hit->t;
        for (const Interval range : {Interval{0, t}, Interval{t, t}, Interval{t, kInfinity}}) {
            const auto again = intersect_triangle(v0, v1, v2, ray, range);
            ASSERT_TRUE(again) << "ray " << i << " range " << range.min << ", " << range.max;
            EXPECT_EQ(again->t, t);
            EXPECT_EQ(again->u, hit->u);
            EXPECT_EQ(again->v, hit->v);
        }
        EXPECT_FALSE(intersect_triangle(v0, v1, v2, ray, {0, std::nextafter(t, 0.0f)}));
        EXPECT_FALSE(intersect_triangle(v0, v1, v2, ray, {std::nextafter(t, kInfinity), 1e30f}));
    }
    EXPECT_GT(hits, 10000);
}

// ---------------------------------------------------------------------------------------------
// Agreement with an exact solve

struct Exact {
    double t, u, v;
};

// o + t d = v0 + u (v1 - v0) + v (v2 - v0) by Cramer's rule in double.
std::optional<Exact> solve_exact(Point3 v0, Point3 v1, Point3 v2, const Ray& ray) {
    const auto minus = [](Point3 a, Point3 b) {
        return std::array<double, 3>{double(a.x) - b.x, double(a.y) - b.y, double(a.z) - b.z};
    };
    const auto e1 = minus(v1, v0), e2 = minus(v2, v0), s = minus(ray.origin, v0);
    const std::array<double, 3> r{ray.direction.x, ray.direction.y, ray.direction.z};
    const auto cross3 = [](const auto& a, const auto& b) {
        return std::array<double, 3>{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                                     a[0] * b[1] - a[1] * b[0]};
    };
    const auto dot3 = [](const auto& a, const auto& b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    };
    const auto p = cross3(r, e2), q = cross3(s, e1);
    const double det = dot3(e1, p);
    if (det == 0) return std::nullopt;
    return Exact{dot3(e2, q) / det, dot3(s, p) / det, dot3(r, q) / det};
}

// Random triangles of every orientation, random rays of every direction (so every choice of kz
// and both signs): clear hits agree with the exact solve in t, u and v; clear misses miss.
TEST(WatertightTriangle, AgreesWithAnExactSolveAwayFromTheEdges) {
    std::mt19937 rng(21);
    std::uniform_real_distribution<float> u(-1, 1);
    int hits = 0, misses = 0;
    for (int i = 0; i < 20000; ++i) {
        const Point3 v0{u(rng), u(rng), u(rng)}, v1{u(rng), u(rng), u(rng)},
            v2{u(rng), u(rng), u(rng)};
        const Point3 origin{3 * u(rng), 3 * u(rng), 3 * u(rng)};
        const Point3 aim{u(rng), u(rng), u(rng)};
        Vector3 d = aim - origin;
        if (i % 10 == 0) d = {0, 0, d.z};  // axis-parallel rays too
        if (length(d) < 1e-3f) continue;
        const Ray ray{origin, normalize(d)};
        // Well-conditioned cases only: no slivers, no rays nearly in the plane.
        const Vector3 n = cross(v1 - v0, v2 - v0);
        if (length(n) < 1e-2f || std::abs(dot(normalize(n), ray.direction)) < 0.05f) continue;
        const auto exact = solve_exact(v0, v1, v2, ray);
        const auto hit = intersect_triangle(v0, v1, v2, ray, {});
        if (!exact) continue;
        const double w = 1 - exact->u - exact->v;
        const double margin = std::min({exact->u, exact->v, w});
        if (margin > 1e-3 && exact->t > 1e-3) {
            ASSERT_TRUE(hit) << "ray " << i;
            ++hits;
            EXPECT_NEAR(hit->t, exact->t, 1e-5 * (1 + exact->t)) << "ray " << i;
            EXPECT_NEAR(hit->u, exact->u, 1e-4) << "ray " << i;
            EXPECT_NEAR(hit->v, exact->v, 1e-4) << "ray " << i;
        } else if (margin < -1e-3 || exact->t < -1e-3) {
            ASSERT_FALSE(hit) << "ray " << i;
            ++misses;
        }
    }
    EXPECT_GT(hits, 1000);
    EXPECT_GT(misses, 1000);
}

// ---------------------------------------------------------------------------------------------
// Rays that must miss

// Rays from random directions at points of the triangle's line (or its point).
void expect_never_hit(const Triangle& tri, std::mt19937& rng) {
    std::uniform_real_distribution<float> u(-1, 1);
    const auto& v = tri.vertices;
    for (int i = 0; i < 3000; ++i) {
        const Point3 p = i % 3 == 0 ? v[std::size_t(i / 3) % 3]
                                    : v[0] + (v[i % 2 ? 1 : 2] - v[0]) * (0.5f + u(rng));
        const Point3 origin = p + Vector3{u(rng), u(rng), u(rng)} * 4;
        Vector3 dir = p - origin;
        if (i % 7 == 0) dir = {0, 0, u(rng)};
        if (length(dir) == 0) continue;
        const Ray ray{origin, normalize(dir)};
        ASSERT_FALSE(tri.intersect(ray, {-kInfinity, kInfinity})) << "ray " << i;
    }
}

TEST(WatertightTriangle, DegenerateTrianglesAreNeverHit) {
    std::mt19937 rng(11);
    const Triangle degenerate[] = {
        {{Point3{0, 0, 0}, Point3{1, 1, 1}, Point3{2, 2, 2}}},  // collinear
        {{Point3{0, 0, 0}, Point3{1, 0, 0}, Point3{3, 0, 0}}},  // collinear along an axis
        {{Point3{0.3f, 0.1f, 0.7f}, Point3{0.3f, 0.1f, 0.7f}, Point3{0.9f, 0.2f, 0.4f}}},
        {{Point3{0.3f, 0.1f, 0.7f}, Point3{0.3f, 0.1f, 0.7f}, Point3{0.3f, 0.1f, 0.7f}}},
    };
    for (const Triangle& t : degenerate) {
        EXPECT_EQ(double_area(t), 0);
        expect_never_hit(t, rng);
    }
    // Random collinear corners (a + s (b - a)) that are exactly collinear in float: zero area.
    std::uniform_int_distribution<int> coordinate(-40, 40);
    const float steps[] = {-1.5f, 0.25f, 0.5f, 0.75f, 2, 3};
    int tested = 0;
    for (int i = 0; i < 300; ++i) {
        const auto point = [&] {
            return Point3{coordinate(rng) / 8.0f, coordinate(rng) / 8.0f, coordinate(rng) / 8.0f};
        };
        const Point3 a = point(), b = point();
        const Triangle t{{a, b, a + (b - a) * steps[i % 6]}};
        if (double_area(t) != 0) continue;
        ++tested;
        expect_never_hit(t, rng);
    }
    EXPECT_GT(tested, 250);
}

TEST(WatertightTriangle, NaNsNeverHit) {
    const Triangle tri{{Point3{0, 0, 0}, Point3{2, 0, 0}, Point3{0, 2, 0}}};
    const Point3 o{0.5f, 0.5f, 3};
    for (const Vector3 d : {Vector3{kNaN, 0, -1}, Vector3{0, kNaN, -1}, Vector3{0, 0, kNaN},
                            Vector3{kNaN, kNaN, kNaN}, Vector3{0, 0, 0}, Vector3{0, 0, -kInfinity},
                            Vector3{kInfinity, 0, -kInfinity}}) {
        EXPECT_FALSE(tri.intersect({o, d}, {-kInfinity, kInfinity}))
            << d.x << " " << d.y << " " << d.z;
    }
    EXPECT_FALSE(tri.intersect({{kNaN, 0.5f, 3}, {0, 0, -1}}, {}));
    EXPECT_FALSE(tri.intersect({o, {0, 0, -1}}, {kNaN, kInfinity}));
    EXPECT_FALSE(tri.intersect({o, {0, 0, -1}}, {0, kNaN}));
    const Triangle bad{{Point3{0, 0, 0}, Point3{kNaN, 0, 0}, Point3{0, 2, 0}}};
    EXPECT_FALSE(bad.intersect({o, {0, 0, -1}}, {}));
}

TEST(WatertightTriangle, RaysParallelToThePlaneMiss) {
    // In the plane itself and beside it, for a triangle in z = 0.
    const Triangle flat{{Point3{0, 0, 0}, Point3{2, 0, 0}, Point3{0, 2, 0}}};
    EXPECT_FALSE(flat.intersect({{-1, 0.5f, 0}, {1, 0, 0}}, {}));
    EXPECT_FALSE(flat.intersect({{-1, 0.5f, 0.25f}, {1, 0, 0}}, {}));
    EXPECT_FALSE(flat.intersect({{-1, -1, 0.25f}, normalize(Vector3{1, 1, 0})}, {}));
    // Random tilted triangles, rays along one of their edges a little above the plane.
    std::mt19937 rng(12);
    std::uniform_real_distribution<float> u(-1, 1);
    for (int i = 0; i < 5000; ++i) {
        const Triangle t{{Point3{u(rng), u(rng), u(rng)}, Point3{u(rng), u(rng), u(rng)},
                          Point3{u(rng), u(rng), u(rng)}}};
        const auto& v = t.vertices;
        const Vector3 n = cross(v[1] - v[0], v[2] - v[0]);
        if (length(n) < 1e-2f) continue;
        const Vector3 along = normalize(v[(i % 2) + 1] - v[0]);
        const Point3 centroid = to_point((to_vector(v[0]) + to_vector(v[1]) + to_vector(v[2])) / 3);
        const Point3 origin = centroid + normalize(n) * (i % 2 ? 0.01f : -0.01f) - along * 4;
        ASSERT_FALSE(t.intersect({origin, along}, {-kInfinity, kInfinity})) << "ray " << i;
    }
}

}  // namespace
}  // namespace glint
