#include "glint/geometry/prism.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "glint/geometry/box.h"
#include "glint/math/constants.h"
#include "shape_property_checks.h"

namespace glint {
namespace {

using testing::RandomRays;

Outline square(float lo, float hi, bool clockwise = false) {
    Outline o;
    const Point2 p[4] = {{lo, lo}, {hi, lo}, {hi, hi}, {lo, hi}};
    for (int i = 0; i < 4; ++i) {
        const int a = clockwise ? 3 - i : i, b = clockwise ? (6 - i) % 4 : (i + 1) % 4;
        append_line(o, p[a], p[b]);
    }
    return o;
}

Prism made(const std::vector<Outline>& outlines, float bottom, float top, bool open = false) {
    auto result = make_prism(outlines, bottom, top, open);
    EXPECT_TRUE(std::holds_alternative<Prism>(result)) << std::get<std::string>(result);
    return std::get<Prism>(result);
}

TEST(Prism, SquareHitsAsTheBoxWithNormalsOutwards) {
    // The unit square from -1 to 1 swept from y = 0 to 2 is the box [-1,1] x [0,2] x [-1,1],
    // whichever way its outline runs.
    const Box box{{-1, 0, -1}, {1, 2, 1}};
    for (const bool clockwise : {false, true}) {
        const Prism prism = made({square(-1, 1, clockwise)}, 0, 2);
        RandomRays rays({0, 1, 0}, 2);
        int hits = 0;
        for (int i = 0; i < 2000; ++i) {
            const Ray ray = rays.next();
            const auto want = box.intersect(ray, {});
            const auto got = prism.intersect(ray, {});
            ASSERT_EQ(bool(want), bool(got)) << i;
            if (!want) continue;
            ++hits;
            ASSERT_NEAR(got->t, want->t, 1e-4f) << i;
            const SurfacePoint a = box.surface_at(ray, *want), b = prism.surface_at(ray, *got);
            // Both agree, except where the ray meets an edge of the box within rounding.
            if (dot(to_vector(a.normal), to_vector(b.normal)) < 0.5f) {
                EXPECT_LT(std::min({std::abs(std::abs(b.p.x) - 1), std::abs(std::abs(b.p.z) - 1),
                                    std::abs(b.p.y), std::abs(b.p.y - 2)}),
                          1e-3f);
                continue;
            }
            EXPECT_NEAR(length(to_vector(b.normal)), 1, 1e-6f);
            EXPECT_GT(dot(to_vector(b.shading_normal), to_vector(b.normal)), 0.999f);
        }
        EXPECT_GT(hits, 300);
    }
}

TEST(Prism, WorkedHitsOnAFrameWithAHole) {
    // A square frame: [-2,2]^2 minus [-1,1]^2, from y = 0 to 1.
    const Prism frame = made({square(-2, 2), square(-1, 1)}, 0, 1);
    // Down the middle of the hole: nothing.
    EXPECT_FALSE(frame.intersect({{0, 5, 0}, {0, -1, 0}}, {}));
    // Down onto the frame at x = 1.5: the top cap at t = 4, normal +y.
    const Ray down{{1.5f, 5, 0}, {0, -1, 0}};
    auto hit = frame.intersect(down, {});
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit->t, 4);
    EXPECT_EQ(frame.surface_at(down, *hit).normal, (Normal3{0, 1, 0}));
    // Then the bottom cap from inside, normal -y.
    hit = frame.intersect(down, {4.001f, kInfinity});
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit->t, 5);
    EXPECT_EQ(frame.surface_at(down, *hit).normal, (Normal3{0, -1, 0}));
    // Along x at mid height: the outer wall at x = -2 (normal -x), the hole's wall at x = -1
    // (normal +x, out of the solid into the hole), then x = 1 (normal -x) and x = 2 (+x).
    const Ray across{{-5, 0.5f, 0}, {1, 0, 0}};
    const float ts[] = {3, 4, 6, 7}, nx[] = {-1, 1, -1, 1};
    float from = 0;
    for (int i = 0; i < 4; ++i) {
        hit = frame.intersect(across, {from, kInfinity});
        ASSERT_TRUE(hit) << i;
        EXPECT_NEAR(hit->t, ts[i], 1e-6f) << i;
        const SurfacePoint sp = frame.surface_at(across, *hit);
        EXPECT_EQ(sp.normal, (Normal3{nx[i], 0, 0})) << i;
        EXPECT_NEAR(sp.uv.y, 0.5f, 1e-6f) << i;
        from = hit->t + 1e-3f;
    }
    EXPECT_FALSE(frame.intersect(across, {from, kInfinity}));
    // Open, the caps are gone and the walls remain.
    const Prism tube = made({square(-2, 2), square(-1, 1)}, 0, 1, true);
    hit = tube.intersect(down, {});
    EXPECT_FALSE(hit);
    EXPECT_TRUE(tube.intersect(across, {}));
}

TEST(Prism, InsideTestIsEvenOdd) {
    const Prism frame = made({square(-2, 2), square(-1, 1)}, 0, 1);
    EXPECT_FALSE(inside_profile(*frame.profile, 0, 0));
    EXPECT_TRUE(inside_profile(*frame.profile, 1.5, 0));
    EXPECT_TRUE(inside_profile(*frame.profile, 0, -1.9));
    EXPECT_FALSE(inside_profile(*frame.profile, 2.5, 0));
}

// A circle of radius r as four quarter curves in power form: the cubic Bezier approximation of
// each quarter, whose radius strays from r by less than 3e-4 r.
Outline circle(float r) {
    Outline o;
    const float k = 0.5522847f * r;
    const Point2 q[4][4] = {{{r, 0}, {r, k}, {k, r}, {0, r}},
                            {{0, r}, {-k, r}, {-r, k}, {-r, 0}},
                            {{-r, 0}, {-r, -k}, {-k, -r}, {0, -r}},
                            {{0, -r}, {k, -r}, {r, -k}, {r, 0}}};
    for (const auto& p : q) {
        // Bernstein to power form: c(s) = A s^3 + B s^2 + C s + D.
        const auto coef = [&](float p0, float p1, float p2, float p3, int i) {
            switch (i) {
                case 0:
                    return -p0 + 3 * p1 - 3 * p2 + p3;
                case 1:
                    return 3 * p0 - 6 * p1 + 3 * p2;
                case 2:
                    return -3 * p0 + 3 * p1;
                default:
                    return p0;
            }
        };
        CubicCurve c;
        Point2* out[4] = {&c.a, &c.b, &c.c, &c.d};
        for (int i = 0; i < 4; ++i) {
            *out[i] = {coef(p[0].x, p[1].x, p[2].x, p[3].x, i),
                       coef(p[0].y, p[1].y, p[2].y, p[3].y, i)};
        }
        append_curve(o, c, 1e-4 * r);
    }
    return o;
}

TEST(Prism, CurvedOutlineIsACylinderWithSmoothNormals) {
    const Prism disk = made({circle(1)}, -1, 1);
    ASSERT_GT(disk.profile->edges.size(), 16u);  // flattened finely enough for 1e-4
    // The curves' ends, evaluated in power form, are joined exactly to the next curve's start.
    const auto& edges = disk.profile->edges;
    for (std::size_t i = 0; i < edges.size(); ++i)
        EXPECT_EQ(edges[i].b, edges[(i + 1) % edges.size()].a);
    testing::PropertyOptions options;
    options.surface_tolerance = 1e-3f;  // the Bezier circle and its flattening
    testing::expect_shape_properties(
        disk,
        [](Point3 p) {
            const float side = std::hypot(p.x, p.z) - 1, cap = std::abs(p.y) - 1;
            return side > cap ? side : cap;
        },
        RandomRays({0, 0, 0}, 1.5f), options);
    // On the wall the shading normal is the radial direction, within the curve's accuracy.
    const Ray ray{{5, 0.2f, 0.3f}, {-1, 0, 0}};
    const auto hit = disk.intersect(ray, {});
    ASSERT_TRUE(hit);
    const SurfacePoint sp = disk.surface_at(ray, *hit);
    const Vector3 radial = normalize(Vector3{sp.p.x, 0, sp.p.z});
    EXPECT_GT(dot(to_vector(sp.shading_normal), radial), 0.99999f);
}

// Brute force over every edge, without the groups' boxes.
std::optional<float> brute_force_t(const Prism& prism, const Ray& ray) {
    std::optional<float> best;
    const auto keep = [&](double t) {
        if (t >= 0 && (!best || t < *best)) best = float(t);
    };
    const double ox = ray.origin.x, oy = ray.origin.y, oz = ray.origin.z;
    const double dx = ray.direction.x, dy = ray.direction.y, dz = ray.direction.z;
    for (const float h : {prism.bottom, prism.top}) {
        const double t = (h - oy) / dy;
        if (inside_profile(*prism.profile, ox + t * dx, oz + t * dz)) keep(t);
    }
    for (const PrismEdge& e : prism.profile->edges) {
        const double ex = double(e.b.x) - e.a.x, ez = double(e.b.y) - e.a.y;
        const double denom = dx * ez - dz * ex;
        if (denom == 0) continue;
        const double wx = e.a.x - ox, wz = e.a.y - oz;
        const double t = (wx * ez - wz * ex) / denom, s = (wx * dz - wz * dx) / denom;
        const double y = oy + t * dy;
        if (s >= 0 && s <= 1 && y >= prism.bottom && y <= prism.top) keep(t);
    }
    return best;
}

TEST(Prism, GroupedEdgesFindWhatBruteForceFinds) {
    // A star of 40 points with a circular hole: many groups, concave, with a hole.
    Outline star;
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> jitter(0.6f, 1.0f);
    std::vector<Point2> points;
    for (int i = 0; i < 40; ++i) {
        const float angle = 2 * kPi * i / 40, r = (i % 2 ? 0.5f : 1.0f) * jitter(rng) * 2;
        points.push_back({r * std::cos(angle), r * std::sin(angle)});
    }
    for (std::size_t i = 0; i < points.size(); ++i)
        append_line(star, points[i], points[(i + 1) % points.size()]);
    const Prism prism = made({star, circle(0.3f)}, -0.5f, 0.5f);
    RandomRays rays({0, 0, 0}, 2);
    int hits = 0;
    for (int i = 0; i < 5000; ++i) {
        const Ray ray = rays.next();
        const auto want = brute_force_t(prism, ray);
        const auto got = prism.intersect(ray, {});
        ASSERT_EQ(bool(want), bool(got)) << i;
        if (want) {
            ++hits;
            ASSERT_NEAR(got->t, *want, 1e-5f * *want) << i;
        }
    }
    EXPECT_GT(hits, 500);
}

TEST(Prism, BadDescriptionsAreRefused) {
    EXPECT_EQ(std::get<std::string>(make_prism({square(-1, 1)}, 1, 1)),
              "prism heights must be finite with bottom < top, got 1 and 1");
    EXPECT_EQ(std::get<std::string>(make_prism({}, 0, 1)), "prism outlines enclose no area");
    Outline flat;
    append_line(flat, {0, 0}, {1, 0});
    append_line(flat, {1, 0}, {0, 0});
    EXPECT_EQ(std::get<std::string>(make_prism({flat}, 0, 1)), "prism outlines enclose no area");
    Outline bad = square(-1, 1);
    bad[1].b.x = std::nanf("");
    EXPECT_EQ(std::get<std::string>(make_prism({bad}, 0, 1)),
              "prism outline 1 has a point that is not finite");
}

TEST(Prism, CurveFlatteningStaysWithinTolerance) {
    // c(s) = (s, s^2): |c''| = 2, so 1e-3 needs n >= sqrt(2 / 8e-3) = 15.8: 16 steps.
    Outline o;
    append_curve(o, {{0, 0}, {0, 1}, {1, 0}, {0, 0}}, 1e-3);
    ASSERT_EQ(o.size(), 16u);
    for (const OutlineEdge& e : o) {
        const float mid_x = (e.a.x + e.b.x) / 2, mid_y = (e.a.y + e.b.y) / 2;
        EXPECT_LE(mid_y - mid_x * mid_x, 1e-3f);
        EXPECT_FLOAT_EQ(e.tangent_a.y, 2 * e.a.x);  // c'(s) = (1, 2s)
    }
    // A straight line in power form is one edge.
    Outline line;
    append_curve(line, {{0, 0}, {0, 0}, {2, 1}, {1, 1}}, 1e-3);
    ASSERT_EQ(line.size(), 1u);
    EXPECT_EQ(line[0].b, (Point2{3, 2}));
}

}  // namespace
}  // namespace glint
