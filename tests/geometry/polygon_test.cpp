// The polygon: worked hits, both inside tests of the notes and where they differ, points on edges
// and vertices, the SPD's gear outline against brute force, validation, and the shape properties.
#include "glint/geometry/polygon.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "shape_property_checks.h"

namespace glint {
namespace {

constexpr InsideTest kBothTests[] = {InsideTest::even_odd, InsideTest::angle_sum};

Polygon polygon_of(std::vector<Point3> vertices, InsideTest test = InsideTest::even_odd) {
    auto result = make_polygon(std::move(vertices), test);
    if (auto* message = std::get_if<std::string>(&result)) ADD_FAILURE() << *message;
    return std::get<Polygon>(result);
}

std::vector<Point3> in_plane_z(std::vector<Point2> outline, float z = 0) {
    std::vector<Point3> points;
    for (const Point2 p : outline) points.push_back({p.x, p.y, z});
    return points;
}

// Hits of a ray straight down onto the plane z = 0 at (x, y): t = 1 and the hit point is exact.
bool hit_from_above(const Polygon& polygon, float x, float y) {
    return bool(polygon.intersect({{x, y, 1}, {0, 0, -1}}, {}));
}

const std::vector<Point2> kSquare = {{0, 0}, {2, 0}, {2, 2}, {0, 2}};
// An L: the 3 x 3 square without its top right 2 x 2 corner; area 5.
const std::vector<Point2> kL = {{0, 0}, {3, 0}, {3, 1}, {1, 1}, {1, 3}, {0, 3}};

// A regular pentagram of circumradius 1: the pentagon's corners taken two steps at a time, so the
// outline winds twice around its centre.
std::vector<Point2> pentagram() {
    std::vector<Point2> points;
    for (int k = 0; k < 5; ++k) {
        const double a = std::numbers::pi / 2 + k * 4 * std::numbers::pi / 5;
        points.push_back({float(std::cos(a)), float(std::sin(a))});
    }
    return points;
}

// A gear face as the SPD's gears write it: 36 teeth of 4 vertices each, a concave 144-gon that is
// star-shaped about its centre. Returns the outline and the outline's radius at an angle.
std::vector<Point2> gear(float inner, float outer) {
    std::vector<Point2> points;
    for (int tooth = 0; tooth < 36; ++tooth) {
        const double a = tooth * 2 * std::numbers::pi / 36, step = 2 * std::numbers::pi / 144;
        const double radii[4] = {inner, outer, outer, inner};
        for (int i = 0; i < 4; ++i) {
            const double b = a + i * step;
            points.push_back({float(radii[i] * std::cos(b)), float(radii[i] * std::sin(b))});
        }
    }
    return points;
}

// Brute force for a star-shaped outline about the origin: the point is inside when it is nearer
// the origin than where its direction leaves the outline.
bool inside_star_shaped(const std::vector<Point2>& outline, double x, double y) {
    for (std::size_t i = 0, j = outline.size() - 1; i < outline.size(); j = i++) {
        // Solve s * (x, y) = a + w * (b - a) for s > 0, w in [0, 1).
        const double ax = outline[j].x, ay = outline[j].y;
        const double ex = outline[i].x - ax, ey = outline[i].y - ay;
        const double det = ex * y - ey * x;
        if (det == 0) continue;
        const double w = (x * ay - y * ax) / det;  // Cramer's rule
        const double s = (ex * ay - ey * ax) / det;
        if (w >= 0 && w < 1 && s > 0) return s > 1;
    }
    return false;
}

// Brute force for any outline: the continuous angle sum with atan2, in double.
int winding_by_atan2(const std::vector<Point2>& outline, double x, double y) {
    double sum = 0;
    for (std::size_t i = 0, j = outline.size() - 1; i < outline.size(); j = i++) {
        const double ax = outline[j].x - x, ay = outline[j].y - y;
        const double bx = outline[i].x - x, by = outline[i].y - y;
        sum += std::atan2(ax * by - ay * bx, ax * bx + ay * by);
    }
    return int(std::lround(sum / (2 * std::numbers::pi)));
}

TEST(Polygon, WorkedHitOnASquare) {
    // N.P = -D with N = (0 0 1), D = -1.5: t = -(D + N.P0) / (N.R) = (1.5 - 4) / (-2 / |R|).
    const Polygon square = polygon_of(in_plane_z(kSquare, 1.5f));
    EXPECT_EQ(square.normal, (Normal3{0, 0, 1}));  // counter-clockwise seen from +z
    EXPECT_EQ(square.plane_offset, 1.5f);
    const Ray ray{{1, 1, 4}, normalize(Vector3{0.25f, 0, -2})};
    const auto hit = square.intersect(ray, {});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 2.5f * std::sqrt(4.0625f) / 2, 1e-5);  // 2.519...
    const SurfacePoint sp = square.surface_at(ray, *hit);
    EXPECT_NEAR(sp.p.x, 1.3125f, 1e-6);  // 1 + 0.25 * 1.25
    EXPECT_FLOAT_EQ(sp.p.z, 1.5f);
    EXPECT_EQ(sp.normal, (Normal3{0, 0, 1}));
    EXPECT_EQ(sp.shading_normal, sp.normal);
    // orthonormal_basis((0 0 1)) is x, y: uv is the offset from vertex 0 in scene units.
    EXPECT_NEAR(sp.uv.x, 1.3125f, 1e-6);
    EXPECT_NEAR(sp.uv.y, 1, 1e-6);
}

TEST(Polygon, BothSidesAreHitAndTheNormalStays) {
    const Polygon square = polygon_of(in_plane_z(kSquare));
    const Ray below{{1, 1, -3}, {0, 0, 1}};
    const auto hit = square.intersect(below, {});
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit->t, 3);
    EXPECT_EQ(square.surface_at(below, *hit).normal, (Normal3{0, 0, 1}));
}

TEST(Polygon, MissesParallelRaysRaysOutsideAndHitsOutsideTheRange) {
    const Polygon square = polygon_of(in_plane_z(kSquare));
    EXPECT_FALSE(square.intersect({{1, 1, 0}, {1, 0, 0}}, {}));   // in the plane, parallel
    EXPECT_FALSE(square.intersect({{3, 1, 1}, {0, 0, -1}}, {}));  // beyond an edge
    EXPECT_FALSE(square.intersect({{1, 1, 1}, {0, 0, 1}}, {}));   // behind the origin
    EXPECT_FALSE(square.intersect({{1, 1, 5}, {0, 0, -1}}, {0, 4.9f}));
    EXPECT_TRUE(square.intersect({{1, 1, 5}, {0, 0, -1}}, {0, 5}));
}

TEST(Polygon, NormalIsRightHandedWithTheVertexOrder) {
    std::vector<Point2> clockwise(kSquare.rbegin(), kSquare.rend());
    EXPECT_EQ(polygon_of(in_plane_z(clockwise)).normal, (Normal3{0, 0, -1}));
}

TEST(Polygon, NewellNormalIsTwiceTheAreaEvenWhereTheFirstCornerMisleads) {
    EXPECT_EQ(newell_normal(in_plane_z(kL)), (Vector3{0, 0, 10}));
    // The first three vertices collinear, or a reflex first corner (whose cross product points
    // the wrong way): Newell still gives the polygon's normal.
    EXPECT_EQ(newell_normal(in_plane_z({{0, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}})),
              (Vector3{0, 0, 8}));
    const std::vector<Point2> reflex_first = {{3, 1}, {1, 1}, {1, 3}, {0, 3}, {0, 0}, {3, 0}};
    const Vector3 e1{-2, 0, 0}, e2{-2, 2, 0};  // (v1 - v0) x (v2 - v0) points to -z
    EXPECT_LT(cross(e1, e2).z, 0);
    EXPECT_EQ(newell_normal(in_plane_z(reflex_first)), (Vector3{0, 0, 10}));
    EXPECT_EQ(polygon_of(in_plane_z(reflex_first)).normal, (Normal3{0, 0, 1}));
}

TEST(Polygon, ConcaveLShapeInATiltedPlane) {
    // The L mapped into the plane spanned by e1 and e2 (sheared, as they are not perpendicular),
    // whose normal e1 x e2 ~ (1 -0.12 0.6) makes the projection drop the x axis.
    const Vector3 e1 = normalize(Vector3{0, 1, 0.2f}), e2 = normalize(Vector3{-0.6f, 0, 1});
    const Normal3 n(normalize(cross(e1, e2)));
    std::vector<Point3> points;
    for (const Point2 p : kL) points.push_back(to_point(e1 * p.x + e2 * p.y));
    for (const InsideTest test : kBothTests) {
        const Polygon l = polygon_of(points, test);
        EXPECT_NEAR(dot(l.normal, n), 1, 1e-6);
        EXPECT_EQ(l.axis_u, 1);  // the normal is dominated by x
        const auto hits = [&](float s, float t) {
            const Point3 target = to_point(e1 * s + e2 * t);
            return bool(l.intersect({target + to_vector(n) * 2, -to_vector(n)}, {}));
        };
        EXPECT_TRUE(hits(0.5f, 2.5f));   // the upright arm
        EXPECT_TRUE(hits(2.5f, 0.5f));   // the foot
        EXPECT_FALSE(hits(2, 2));        // the notch
        EXPECT_FALSE(hits(-0.5f, 1));    // beside it
        EXPECT_FALSE(hits(2.9f, 2.9f));  // in the bounds, outside the L
    }
}

TEST(Polygon, PentagramCentreIsOutsideForEvenOddAndInsideForTheAngleSum) {
    const std::vector<Point2> star = pentagram();
    // From the centre, a ray to +x crosses two edges; the outline winds twice around it.
    EXPECT_EQ(crossing_count(star, 0, 0), 2);
    EXPECT_EQ(winding_number(star, 0, 0), 2);
    EXPECT_FALSE(hit_from_above(polygon_of(in_plane_z(star), InsideTest::even_odd), 0, 0));
    EXPECT_TRUE(hit_from_above(polygon_of(in_plane_z(star), InsideTest::angle_sum), 0, 0));
    // A tip is wound once: inside for both. Beyond the tips, outside for both.
    for (const InsideTest test : kBothTests) {
        const Polygon p = polygon_of(in_plane_z(star), test);
        EXPECT_TRUE(hit_from_above(p, 0, 0.8f));
        EXPECT_FALSE(hit_from_above(p, 0.7f, 0.7f));
    }
    EXPECT_EQ(winding_number(star, 0, 0.8), 1);
    EXPECT_EQ(winding_number(star, 0.7, 0.7), 0);
}

TEST(Polygon, PentagramTestsDifferExactlyOnTheDoublyWoundCentre) {
    const std::vector<Point2> star = pentagram();
    // The inner pentagon has circumradius cos 72 / cos 36 and inradius cos 72.
    const double circumradius = std::cos(0.4 * std::numbers::pi) / std::cos(0.2 * std::numbers::pi);
    const double inradius = std::cos(0.4 * std::numbers::pi);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> coordinate(-1.1, 1.1);
    int differing = 0;
    for (int i = 0; i < 20000; ++i) {
        const double x = coordinate(rng), y = coordinate(rng), r = std::hypot(x, y);
        const bool even_odd = inside_outline(star, x, y, InsideTest::even_odd);
        const bool angle_sum = inside_outline(star, x, y, InsideTest::angle_sum);
        const int w = winding_number(star, x, y);
        ASSERT_EQ(w, winding_by_atan2(star, x, y)) << x << ", " << y;
        ASSERT_EQ(even_odd, w % 2 != 0);
        if (even_odd != angle_sum) {
            ++differing;
            ASSERT_TRUE(angle_sum && std::abs(w) == 2);
            ASSERT_LT(r, circumradius + 1e-9);
        }
        if (r < inradius - 1e-9) {
            ASSERT_NE(even_odd, angle_sum);
        }
        if (r > circumradius + 1e-9) {
            ASSERT_EQ(even_odd, angle_sum);
        }
    }
    EXPECT_GT(differing, 100);
}

TEST(Polygon, InsideTestsAgreeOnSimplePolygonsAtRandomPoints) {
    std::mt19937 rng(11);
    std::vector<std::vector<Point2>> outlines = {kSquare, kL, gear(0.8f, 1)};
    // Random star-shaped outlines: simple, often very concave.
    for (int k = 0; k < 20; ++k) {
        std::uniform_real_distribution<float> radius(0.05f, 1);
        const int n = 3 + k * 5;
        std::vector<Point2> outline;
        for (int i = 0; i < n; ++i) {
            const double a = 2 * std::numbers::pi * (i + 0.5 * radius(rng)) / n;
            const float r = radius(rng);
            outline.push_back({float(r * std::cos(a)), float(r * std::sin(a))});
        }
        outlines.push_back(outline);
    }
    for (std::size_t k = 0; k < outlines.size(); ++k) {
        const auto& outline = outlines[k];
        std::uniform_real_distribution<double> coordinate(-1.2, 3.2);
        for (int i = 0; i < 2000; ++i) {
            const double x = coordinate(rng), y = coordinate(rng);
            const int w = winding_number(outline, x, y);
            ASSERT_LE(std::abs(w), 1) << "outline " << k;
            ASSERT_EQ(w, winding_by_atan2(outline, x, y)) << "outline " << k;
            ASSERT_EQ(crossing_count(outline, x, y) % 2 == 1, w != 0) << "outline " << k;
        }
    }
}

// Polygons that tile [0,4]^2, in both orientations, with reflex vertices, a slanted shared edge and
// vertices where three tiles meet. Every grid point on a quarter unit, on edges and vertices too,
// must belong to exactly one tile, for both tests: no cracks and no double hits.
// A 4 x 4 square with a 2 x 2 hole and, apart, a unit square: the ring and the island are
// inside, the hole and the gap outside, with the hole wound either way for the even-odd test and
// against its outline for the angle sum.
TEST(Polygon, BridgedOutlinesHaveHolesAndIslands) {
    const std::vector<Point3> outer = in_plane_z({{0, 0}, {4, 0}, {4, 4}, {0, 4}});
    const std::vector<Point3> against = in_plane_z({{1, 1}, {1, 3}, {3, 3}, {3, 1}});
    const std::vector<Point3> along = in_plane_z({{1, 1}, {3, 1}, {3, 3}, {1, 3}});
    const std::vector<Point3> island = in_plane_z({{6, 0}, {7, 0}, {7, 1}, {6, 1}});
    const auto check = [](const Polygon& polygon) {
        EXPECT_TRUE(hit_from_above(polygon, 0.5f, 2));  // in the ring
        EXPECT_TRUE(hit_from_above(polygon, 3.5f, 3.5f));
        EXPECT_FALSE(hit_from_above(polygon, 2, 2));  // in the hole
        EXPECT_FALSE(hit_from_above(polygon, 1.5f, 2.5f));
        EXPECT_TRUE(hit_from_above(polygon, 6.5f, 0.5f));  // on the island
        EXPECT_FALSE(hit_from_above(polygon, 5, 0.5f));    // between
        // The bridges, from (0, 0) to (1, 1) and to (6, 0), are not edges that count.
        EXPECT_TRUE(hit_from_above(polygon, 0.5f, 0.4f));
        EXPECT_TRUE(hit_from_above(polygon, 3, 0.5f));
    };
    const std::vector<std::vector<Point3>> even_odd[] = {{outer, against, island},
                                                         {outer, along, island}};
    for (const auto& outlines : even_odd) {
        const std::vector<Point3> joined = bridged_outline(outlines);
        EXPECT_EQ(joined.size(), 4u + 6 + 6);
        check(polygon_of(joined));
    }
    const std::vector<std::vector<Point3>> wound = {outer, against, island};
    check(polygon_of(bridged_outline(wound), InsideTest::angle_sum));
    // The vector area is the outline's less the hole's plus the island's: 16 - 4 + 1.
    EXPECT_NEAR(length(newell_normal(bridged_outline(wound))), 2 * 13, 1e-4);
}

TEST(Polygon, PointsOnSharedEdgesAndVerticesBelongToExactlyOneTile) {
    const std::vector<std::vector<Point2>> tiles = {
        {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}},  // an L, counter-clockwise
        {{1, 1}, {1, 2}, {2, 2}, {2, 1}},                  // the square in its notch, clockwise
        {{2, 0}, {4, 0}, {4, 2}, {2, 2}},                  //
        {{0, 2}, {2, 2}, {4, 2}, {4, 4}, {2, 3}, {0, 4}},  // concave at (2, 3)
        {{0, 4}, {2, 3}, {4, 4}},                          // the triangle above it
    };
    for (const InsideTest test : kBothTests) {
        std::vector<Polygon> polygons;
        for (const auto& tile : tiles) polygons.push_back(polygon_of(in_plane_z(tile), test));
        for (int i = 1; i < 16; ++i) {
            for (int j = 1; j < 16; ++j) {
                const float x = i / 4.0f, y = j / 4.0f;
                int owners = 0, owners_below = 0;
                for (const Polygon& p : polygons) {
                    owners += hit_from_above(p, x, y);
                    owners_below += bool(p.intersect({{x, y, -1}, {0, 0, 1}}, {}));
                }
                ASSERT_EQ(owners, 1) << "(" << x << ", " << y << ")";
                ASSERT_EQ(owners_below, 1) << "(" << x << ", " << y << ")";
            }
        }
    }
}

TEST(Polygon, EdgesAndVerticesFollowTheNotesZeroCountsAsPlusRule) {
    // The point is classified as if moved an infinitesimal step to -x and -y: the square's left
    // and bottom edges are out, its right and top edges in, and only its top right corner is in.
    for (const InsideTest test : kBothTests) {
        const Polygon square = polygon_of(in_plane_z(kSquare), test);
        EXPECT_FALSE(hit_from_above(square, 0, 1));
        EXPECT_FALSE(hit_from_above(square, 1, 0));
        EXPECT_TRUE(hit_from_above(square, 2, 1));
        EXPECT_TRUE(hit_from_above(square, 1, 2));
        EXPECT_FALSE(hit_from_above(square, 0, 0));
        EXPECT_FALSE(hit_from_above(square, 2, 0));
        EXPECT_FALSE(hit_from_above(square, 0, 2));
        EXPECT_TRUE(hit_from_above(square, 2, 2));
    }
}

TEST(Polygon, GearOf144VerticesMatchesBruteForce) {
    const std::vector<Point2> outline = gear(0.9f, 1);
    ASSERT_EQ(outline.size(), 144u);
    // Placed in a tilted plane at an offset, with rays along the normal.
    const Vector3 e1 = normalize(Vector3{1, 0.3f, 0}), e2 = normalize(Vector3{-0.2f, 0.4f, 1});
    const Vector3 e2_perp = normalize(e2 - e1 * dot(e1, e2));
    const Point3 origin{0.5f, -2, 3};
    std::vector<Point3> points;
    for (const Point2 p : outline) points.push_back(origin + e1 * p.x + e2_perp * p.y);
    const Vector3 n = normalize(cross(e1, e2_perp));
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> coordinate(-1.05, 1.05);
    for (const InsideTest test : kBothTests) {
        const Polygon polygon = polygon_of(points, test);
        EXPECT_NEAR(dot(polygon.normal, n), 1, 1e-6);
        int hits = 0, checked = 0;
        for (int i = 0; i < 20000; ++i) {
            const double s = coordinate(rng), t = coordinate(rng);
            const bool expected = inside_star_shaped(outline, s, t);
            ASSERT_EQ(inside_outline(outline, s, t, test), expected) << s << ", " << t;
            // In 3D, float rounding blurs the outline by about 1e-6: points that near it are
            // left out.
            bool near_edge = false;
            for (std::size_t a = 0, b = outline.size() - 1; a < outline.size(); b = a++) {
                const double ex = outline[a].x - outline[b].x, ey = outline[a].y - outline[b].y;
                const double w = std::clamp(
                    ((s - outline[b].x) * ex + (t - outline[b].y) * ey) / (ex * ex + ey * ey), 0.0,
                    1.0);
                near_edge |=
                    std::hypot(s - outline[b].x - w * ex, t - outline[b].y - w * ey) < 1e-4;
            }
            if (near_edge) continue;
            ++checked;
            const Point3 target = origin + e1 * float(s) + e2_perp * float(t);
            const bool hit = bool(polygon.intersect({target + n * 3, -n}, {}));
            ASSERT_EQ(hit, expected) << s << ", " << t;
            hits += hit;
        }
        EXPECT_GT(hits, 5000);
        EXPECT_GT(checked, 19000);
    }
}

TEST(Polygon, BandedCrossingCountEqualsTheFullCount) {
    // The gear, and random outlines of many vertices (self-intersecting ones included), at
    // random points and at points level with vertices and with the bands' boundaries.
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> u(-1, 1);
    std::vector<std::vector<Point2>> outlines{gear(0.9f, 1)};
    for (int k = 0; k < 20; ++k) {
        std::vector<Point2> random(16 + 10 * k);
        for (Point2& p : random) p = {u(rng), u(rng)};
        outlines.push_back(random);
    }
    for (const auto& outline : outlines) {
        const Polygon polygon = polygon_of(in_plane_z(outline));
        ASSERT_FALSE(polygon.outline->bands.start.empty()) << outline.size() << " vertices";
        std::vector<double> ys;
        for (const Point2 p : outline) ys.push_back(p.y);
        const EdgeBands& b = polygon.outline->bands;
        for (std::size_t k = 0; k + 1 < b.start.size(); ++k)
            ys.push_back(b.v_min + double(k) / b.scale);
        for (int i = 0; i < 2000; ++i) ys.push_back(u(rng) * 1.1);
        for (std::size_t j = 0; j < ys.size(); ++j) {
            const double y = ys[j];
            // Anywhere, and level with a vertex on both axes (points on vertices and edges).
            for (const double x : {double(u(rng)), double(outline[j % outline.size()].x)}) {
                ASSERT_EQ(crossing_count(polygon.outline->projected, b, x, y),
                          crossing_count(polygon.outline->projected, x, y))
                    << outline.size() << " vertices at (" << x << ", " << y << ")";
            }
        }
    }
}

TEST(Polygon, BadVerticesGiveAMessage) {
    const auto message = [](std::vector<Point3> v) {
        auto result = make_polygon(std::move(v));
        return std::holds_alternative<std::string>(result) ? std::get<std::string>(result)
                                                           : std::string("(valid)");
    };
    EXPECT_EQ(message({{0, 0, 0}, {1, 0, 0}}), "a polygon needs at least 3 vertices, got 2");
    EXPECT_EQ(message({{0, 0, 0}, {1, 0, 0}, {0, NAN, 0}}), "polygon vertex 3 is not finite");
    EXPECT_EQ(message({{0, 0, 0}, {1, 0, 0}, {0, 1, INFINITY}}), "polygon vertex 3 is not finite");
    const std::string no_area =
        "polygon has no area: its vertices are collinear or coincide (or its loops wind both "
        "ways and cancel)";
    EXPECT_EQ(message({{0, 0, 0}, {1, 1, 1}, {3, 3, 3}}), no_area);
    EXPECT_EQ(message({{1, 2, 3}, {1, 2, 3}, {1, 2, 3}, {1, 2, 3}}), no_area);
    EXPECT_EQ(message({{0, 0, 0}, {1, 1, 0}, {1, 0, 0}, {0, 1, 0}}), no_area);  // a bow tie
    EXPECT_EQ(message({{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0.2f}}),
              "polygon vertices are not coplanar: vertex 4 is 0.2 off the plane of the others");
    EXPECT_EQ(message({{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0.001f}}), "(valid)");
    // The mistyped vertex is named, not merely the one farthest from a plane it tilted.
    const std::vector<Point3> typo = {{0, 0, 0}, {2, 0, 0}, {3, 1, 0.5f}, {2, 2, 0}, {0, 2, 0}};
    const auto problem = polygon_problem(typo);
    ASSERT_TRUE(problem);
    EXPECT_EQ(problem->vertex, 2u);
    EXPECT_EQ(problem->message,
              "polygon vertices are not coplanar: vertex 3 is 0.5 off the plane of the others");
    EXPECT_FALSE(polygon_problem(in_plane_z(kL)));
    EXPECT_EQ(message({{0, 0, 0}, {2e-7f, 0, 0}, {0, 2e-7f, 0}}), "(valid)");  // tiny is fine
}

TEST(Polygon, CopiesAreIndependentValues) {
    Polygon a = polygon_of(in_plane_z(kL));
    const Polygon b = a;
    a = polygon_of(in_plane_z(kSquare));
    EXPECT_TRUE(hit_from_above(b, 0.5f, 2.5f));
    EXPECT_FALSE(hit_from_above(a, 0.5f, 2.5f));
    EXPECT_EQ(b.bounds().max, (Point3{3, 3, 0}));
}

using testing::expect_shape_properties;
using testing::PropertyOptions;
using testing::RandomRays;

// Planar: a ray leaving the surface never meets it again, whatever the outline; the normal is
// the gradient of the plane's function.
void expect_polygon_properties(const Polygon& p) {
    PropertyOptions options;
    options.convex = true;
    options.normal_matches_gradient = true;
    const Bounds3 box = p.bounds();
    const float size = length(box.diagonal()) / 3;
    expect_shape_properties(
        p, [&](Point3 q) { return dot(p.normal, q - p.vertices[0]); },
        RandomRays(box.center(), size), options);
}

TEST(ShapeProperties, Polygon) {
    const Vector3 e1 = normalize(Vector3{1, 0.3f, 0.1f}), e2 = normalize(Vector3{-0.2f, 1, 0.4f});
    const auto tilted = [&](const std::vector<Point2>& outline) {
        std::vector<Point3> points;
        for (const Point2 q : outline)
            points.push_back(Point3{0.2f, -0.1f, 0.3f} + e1 * q.x + e2 * q.y);
        return points;
    };
    for (const InsideTest test : kBothTests) {
        expect_polygon_properties(polygon_of(tilted(kSquare), test));
        expect_polygon_properties(polygon_of(tilted(kL), test));
        expect_polygon_properties(polygon_of(tilted(pentagram()), test));
        expect_polygon_properties(polygon_of(tilted(gear(0.7f, 1)), test));
    }
}

}  // namespace
}  // namespace glint
