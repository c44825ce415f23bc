// Cone coverage (Amanatides 1984): the disk overlaps with worked numbers, a half-covered cone
// gives one half, and the fractions of spheres, planes and polygons against numerical
// integration: the share of rays spread evenly over the cone's cross-section that hit the shape.
#include "glint/geometry/cone_coverage.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "glint/geometry/polygon.h"
#include "glint/math/constants.h"

namespace glint {
namespace {

TEST(ConeCoverage, DiskOverlapsWorkedExamples) {
    // A square that holds the unit disk: all of it; the half-plane x < 0 within a big square:
    // half; a small triangle inside: its own area.
    const std::array<Point2, 4> big{{{-2, -2}, {2, -2}, {2, 2}, {-2, 2}}};
    EXPECT_NEAR(disk_polygon_overlap(big, 1), kPi, 1e-5f);
    const std::array<Point2, 4> left{{{-2, -2}, {0, -2}, {0, 2}, {-2, 2}}};
    EXPECT_NEAR(disk_polygon_overlap(left, 1), kPi / 2, 1e-5f);
    const std::array<Point2, 3> small{{{0.1f, 0.1f}, {0.4f, 0.1f}, {0.1f, 0.5f}}};
    EXPECT_NEAR(disk_polygon_overlap(small, 1), 0.3f * 0.4f / 2, 1e-6f);
    // Clockwise corners count the same.
    const std::array<Point2, 3> clockwise{{{0.1f, 0.1f}, {0.1f, 0.5f}, {0.4f, 0.1f}}};
    EXPECT_NEAR(disk_polygon_overlap(clockwise, 1), 0.06f, 1e-6f);
    // Two unit disks one apart share 2 pi / 3 - sqrt(3) / 2.
    EXPECT_NEAR(disk_disk_overlap(1, 1, 1), 2 * kPi / 3 - std::sqrt(3.0f) / 2, 1e-5f);
    EXPECT_FLOAT_EQ(disk_disk_overlap(1, 0.5f, 0.2f), kPi * 0.25f);  // one inside the other
    EXPECT_EQ(disk_disk_overlap(1, 1, 2.5f), 0);
}

const RayCone kCone{{0, 0, 0}, {0, 0, 1}, 0.02f};

TEST(ConeCoverage, AConeHalfCoveredGivesOneHalf) {
    // A square whose edge runs along the axis, and a plane the axis runs along.
    const std::array<Point3, 4> square{{{0, -1, 5}, {1, -1, 5}, {1, 1, 5}, {0, 1, 5}}};
    const auto polygon = cone_coverage(kCone, square);
    ASSERT_TRUE(polygon);
    EXPECT_NEAR(polygon->fraction, 0.5f, 1e-4f);
    EXPECT_NEAR(polygon->depth, 5, 1e-4f);
    const auto plane = cone_coverage(kCone, Plane{{0, -1, 0}, {0, 1, 0}});
    ASSERT_TRUE(plane);
    EXPECT_NEAR(plane->fraction, 0.5f, 1e-4f);
}

// The share of n x n rays, spread evenly over the cone's cross-section at distance 1, that
// `hits` says meet the shape.
template <class Hits>
float integrated(const RayCone& cone, Hits hits) {
    Vector3 s, t;
    orthonormal_basis(cone.axis, s, t);
    constexpr int n = 400;
    int inside = 0, hit = 0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const float x = (2 * (float(i) + 0.5f) / n - 1), y = (2 * (float(j) + 0.5f) / n - 1);
            if (x * x + y * y > 1) continue;
            ++inside;
            const Vector3 d = normalize(cone.axis + s * (x * cone.spread) + t * (y * cone.spread));
            if (hits(Ray{cone.apex, d})) ++hit;
        }
    return float(hit) / float(inside);
}

TEST(ConeCoverage, SpheresAgainstNumericalIntegration) {
    for (const Sphere& sphere : {Sphere{{0.05f, 0.02f, 5}, 0.1f}, Sphere{{0.1f, 0, 4}, 0.05f},
                                 Sphere{{0, -0.3f, 12}, 0.2f}, Sphere{{0.02f, 0, 3}, 0.01f}}) {
        const auto c = cone_coverage(kCone, sphere);
        const float expected = integrated(kCone, [&](const Ray& r) {
            return sphere.intersect(r, {0, kInfinity}).has_value();
        });
        ASSERT_EQ(c.has_value(), expected > 0);
        if (!c) continue;
        EXPECT_NEAR(c->fraction, expected, 0.01f);
        // The direction to shade finds the sphere.
        EXPECT_TRUE(sphere.intersect(Ray{kCone.apex, c->toward}, {0, kInfinity}));
    }
}

TEST(ConeCoverage, PolygonsAndPlanesAgainstNumericalIntegration) {
    const std::array<Point3, 3> triangle{{{-0.05f, -0.04f, 4}, {0.1f, 0.02f, 4.5f}, {0, 0.08f, 5}}};
    const std::array<Point3, 5> dart{
        {{0.02f, 0, 3}, {0.2f, -0.1f, 3}, {0.1f, 0, 3}, {0.2f, 0.1f, 3}, {0.02f, 0.01f, 3}}};
    // Leaning back past the apex's side: clipped to the part in front of it.
    const std::array<Point3, 4> behind{{{-1, -1, 3}, {1, -1, 3}, {1, 1, -1}, {-1, 1, -1}}};
    auto check = [&](std::span<const Point3> corners) {
        const auto made = make_polygon({corners.begin(), corners.end()}, InsideTest::even_odd);
        ASSERT_TRUE(std::holds_alternative<Polygon>(made));
        const Polygon& polygon = std::get<Polygon>(made);
        const auto c = cone_coverage(kCone, corners);
        const float expected = integrated(kCone, [&](const Ray& r) {
            return polygon.intersect(r, {0, kInfinity}).has_value();
        });
        ASSERT_EQ(c.has_value(), expected > 0);
        if (!c) return;
        EXPECT_NEAR(c->fraction, expected, 0.01f);
        EXPECT_TRUE(polygon.intersect(Ray{kCone.apex, c->toward}, {0, kInfinity}));
    };
    check(triangle);
    check(dart);
    check(behind);
    for (const Plane& plane : {Plane{{0, -0.1f, 0}, {0, 1, 0}},
                               Plane{{0, 0, 6}, Normal3(normalize(Vector3{0, 1, -0.01f}))},
                               Plane{{0, 0, 3}, Normal3(normalize(Vector3{0.3f, 0.2f, -1}))}}) {
        const auto c = cone_coverage(kCone, plane);
        const float expected = integrated(kCone, [&](const Ray& r) {
            return plane.intersect(r, {0, kInfinity}).has_value();
        });
        ASSERT_EQ(c.has_value(), expected > 0);
        if (!c) continue;
        EXPECT_NEAR(c->fraction, expected, 0.01f);
        EXPECT_TRUE(plane.intersect(Ray{kCone.apex, c->toward}, {0, kInfinity}));
    }
}

}  // namespace
}  // namespace glint
