#include "glint/geometry/lathe.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "glint/geometry/cone.h"
#include "glint/geometry/spline_outlines.h"
#include "glint/math/constants.h"
#include "shape_property_checks.h"

namespace glint {
namespace {

using testing::RandomRays;

Lathe made(const std::vector<Point2>& points, SplineKind kind = SplineKind::linear) {
    auto curve = spline_curve(kind, points);
    EXPECT_TRUE(std::holds_alternative<Outline>(curve)) << std::get<std::string>(curve);
    auto lathe = make_lathe(std::get<Outline>(curve));
    EXPECT_TRUE(std::holds_alternative<Lathe>(lathe)) << std::get<std::string>(lathe);
    return std::get<Lathe>(lathe);
}

TEST(Lathe, ASlantedPieceIsTheConeFrustum) {
    // From radius 1 at y = 0 to radius 0.25 at y = 2: glint's open cone.
    const Lathe lathe = made({{1, 0}, {0.25f, 2}});
    EXPECT_FALSE(lathe.closed);
    const Cone cone{{0, 0, 0}, 1, {0, 2, 0}, 0.25f, false};
    RandomRays rays({0, 1, 0}, 1.5f);
    int hits = 0;
    for (int i = 0; i < 2000; ++i) {
        const Ray ray = rays.next();
        const auto want = cone.intersect(ray, {});
        const auto got = lathe.intersect(ray, {});
        ASSERT_EQ(bool(want), bool(got)) << i;
        if (!want) continue;
        ++hits;
        ASSERT_NEAR(got->t, want->t, 1e-4f) << i;
        const SurfacePoint a = cone.surface_at(ray, *want), b = lathe.surface_at(ray, *got);
        // The open curve's normal is to the right of its way: outwards for this one.
        EXPECT_GT(dot(to_vector(a.normal), to_vector(b.normal)), 0.9999f) << i;
    }
    EXPECT_GT(hits, 300);
}

TEST(Lathe, WorkedHitsOnAClosedTube) {
    // The square (1, 0) (2, 0) (2, 1) (1, 1) turned round y: a tube of radii 1 and 2, a solid.
    const Lathe tube = made({{1, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 0}});
    EXPECT_TRUE(tube.closed);
    const Ray across{{-5, 0.5f, 0}, {1, 0, 0}};
    const float ts[] = {3, 4, 6, 7}, nx[] = {-1, 1, -1, 1};
    float from = 0;
    for (int i = 0; i < 4; ++i) {
        const auto hit = tube.intersect(across, {from, kInfinity});
        ASSERT_TRUE(hit) << i;
        EXPECT_NEAR(hit->t, ts[i], 1e-5f) << i;
        const SurfacePoint sp = tube.surface_at(across, *hit);
        EXPECT_NEAR(sp.normal.x, nx[i], 1e-6f) << i;  // out of the solid, into the hole
        from = hit->t + 1e-3f;
    }
    // Down onto the ring: the top at y = 1, normal +y; down the hole: nothing.
    const Ray down{{0, 5, 1.5f}, {0, -1, 0}};
    const auto top = tube.intersect(down, {});
    ASSERT_TRUE(top);
    EXPECT_NEAR(top->t, 4, 1e-5f);
    EXPECT_NEAR(tube.surface_at(down, *top).normal.y, 1, 1e-6f);
    EXPECT_FALSE(tube.intersect({{0, 5, 0}, {0, -1, 0}}, {}));
    // Its bounds: radius 2, heights 0 to 1.
    EXPECT_EQ(tube.bounds().min, (Point3{-2, 0, -2}));
    EXPECT_EQ(tube.bounds().max, (Point3{2, 1, 2}));
}

TEST(Lathe, ACurvedProfileShadesSmoothly) {
    // A Bezier quarter circle from (1, 0) to (0, 1) and back down the axis: a hemisphere of
    // radius 1, the shading normal radial from the origin.
    const float k = 0.5522847f;
    auto curve = std::get<Outline>(
        spline_curve(SplineKind::bezier, std::vector<Point2>{{1, 0}, {1, k}, {k, 1}, {0, 1}}));
    append_line(curve, {0, 1}, {0, 0});
    append_line(curve, {0, 0}, {1, 0});
    const Lathe dome = std::get<Lathe>(make_lathe(curve));
    EXPECT_TRUE(dome.closed);
    testing::PropertyOptions options;
    options.surface_tolerance = 1e-3f;
    testing::expect_shape_properties(
        dome,
        [](Point3 p) {
            const float sphere = length(to_vector(p)) - 1;
            return std::abs(p.y) < std::abs(sphere) ? p.y : sphere;
        },
        RandomRays({0, 0.5f, 0}, 1.2f), options);
    const Ray ray{{0.3f, 0.5f, -5}, {0, 0, 1}};
    const auto hit = dome.intersect(ray, {});
    ASSERT_TRUE(hit);
    const SurfacePoint sp = dome.surface_at(ray, *hit);
    EXPECT_GT(dot(to_vector(sp.shading_normal), normalize(to_vector(sp.p))), 0.99999f);
}

// Brute force over every piece: the runs' cylinders skip only what no piece would hit.
TEST(Lathe, GroupedPiecesFindWhatBruteForceFinds) {
    std::vector<Point2> points;
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> radius(0.3f, 1.5f);
    for (int i = 0; i < 60; ++i) points.push_back({radius(rng), -1.5f + 3 * float(i) / 59});
    const Lathe vase = made(points, SplineKind::cubic);
    RandomRays rays({0, 0, 0}, 1.6f);
    int hits = 0;
    for (int i = 0; i < 1000; ++i) {
        const Ray ray = rays.next();
        std::optional<float> want;
        for (std::size_t k = 0; k < vase.profile->pieces.size(); ++k) {
            Lathe one = vase;
            auto single = std::make_shared<LatheProfile>();
            single->pieces = {vase.profile->pieces[k]};
            single->group_radius = {vase.profile->radius};
            single->group_bottom = {vase.profile->bottom};
            single->group_top = {vase.profile->top};
            single->radius = vase.profile->radius;
            single->bottom = vase.profile->bottom;
            single->top = vase.profile->top;
            one.profile = single;
            if (const auto h = one.intersect(ray, {}); h && (!want || h->t < *want)) want = h->t;
        }
        const auto got = vase.intersect(ray, {});
        ASSERT_EQ(bool(want), bool(got)) << i;
        if (want) {
            ++hits;
            ASSERT_NEAR(got->t, *want, 1e-5f * *want) << i;
        }
    }
    EXPECT_GT(hits, 150);
}

TEST(Lathe, SorCurvesInterpolateTheSquaredRadius) {
    // (1, 0) (1, 1) (2, 2) (2, 3): on y in [1, 2], r^2 runs from 1 to 4 with slopes
    // 2 r1 (r2 - r0) / (y2 - y0) = 1 and 2 r2 (r3 - r1) / (y3 - y1) = 2; halfway, the Hermite
    // cubic gives 1/2 + 1/8 + 2 - 1/4 = 2.375.
    const auto curve =
        std::get<Outline>(sor_curve(std::vector<Point2>{{1, 0}, {1, 1}, {2, 2}, {2, 3}}, true));
    ASSERT_EQ(curve.size(), 32u);
    EXPECT_EQ(curve.front().a, (Point2{1, 1}));
    EXPECT_EQ(curve.back().b, (Point2{2, 2}));
    EXPECT_NEAR(curve[16].a.x, std::sqrt(2.375f), 1e-6f);
    EXPECT_NEAR(curve[16].a.y, 1.5f, 1e-6f);
    // Capped, a constant radius is a closed cylinder from y = 1 to 2: walls and caps.
    const Lathe can = std::get<Lathe>(make_lathe(
        std::get<Outline>(sor_curve(std::vector<Point2>{{1, 0}, {1, 1}, {1, 2}, {1, 3}}, false))));
    EXPECT_TRUE(can.closed);
    auto hit = can.intersect({{-5, 1.5f, 0}, {1, 0, 0}}, {});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 4, 1e-5f);
    hit = can.intersect({{0.5f, 5, 0}, {0, -1, 0}}, {});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 3, 1e-5f);
    EXPECT_EQ(std::get<std::string>(
                  sor_curve(std::vector<Point2>{{1, 0}, {1, 1}, {1, 1}, {1, 3}}, false)),
              "heights must rise along the curve: point 3 is not above point 2");
}

TEST(Lathe, BadCurvesAreRefused) {
    EXPECT_EQ(std::get<std::string>(make_lathe({})), "lathe curve is empty");
    EXPECT_EQ(std::get<std::string>(spline_curve(
                  SplineKind::bezier, std::vector<Point2>{{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 2}})),
              "a bezier spline takes four points a curve: 5 points are not a multiple of 4");
    EXPECT_EQ(std::get<std::string>(
                  spline_curve(SplineKind::quadratic, std::vector<Point2>{{0, 0}, {1, 0}})),
              "a quadratic spline needs at least 3 points, got 2");
}

}  // namespace
}  // namespace glint
