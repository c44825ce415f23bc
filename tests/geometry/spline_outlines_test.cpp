#include "glint/geometry/spline_outlines.h"

#include <gtest/gtest.h>

namespace glint {
namespace {

SplineOutlines outlines_of(SplineKind kind, std::vector<Point2> points) {
    auto result = spline_outlines(kind, points);
    EXPECT_TRUE(std::holds_alternative<SplineOutlines>(result)) << std::get<std::string>(result);
    return std::get<SplineOutlines>(result);
}

// Whether the outline passes through p (as the end of one of its edges).
bool passes_through(const Outline& outline, Point2 p) {
    for (const OutlineEdge& e : outline) {
        if (std::abs(e.b.x - p.x) < 1e-6f && std::abs(e.b.y - p.y) < 1e-6f) return true;
    }
    return false;
}

TEST(SplineOutlines, LinearOutlinesCloseWhereTheirFirstPointRepeats) {
    // POV-Ray's prism of a square with a square hole: two sub-polygons, each closed.
    const auto s = outlines_of(SplineKind::linear, {{-2, -2},
                                                    {2, -2},
                                                    {2, 2},
                                                    {-2, 2},
                                                    {-2, -2},
                                                    {-1, -1},
                                                    {1, -1},
                                                    {1, 1},
                                                    {-1, 1},
                                                    {-1, -1}});
    ASSERT_EQ(s.outlines.size(), 2u);
    EXPECT_EQ(s.outlines[0].size(), 4u);
    EXPECT_EQ(s.outlines[1].size(), 4u);
    EXPECT_EQ(s.outlines[1][0].a, (Point2{-1, -1}));
    EXPECT_EQ(s.closed_by_line, 0);
    // Left open, the last outline is closed by a straight edge, and said so.
    const auto open = outlines_of(SplineKind::linear, {{0, 0}, {1, 0}, {0, 1}});
    ASSERT_EQ(open.outlines.size(), 1u);
    EXPECT_EQ(open.outlines[0].size(), 3u);
    EXPECT_EQ(open.closed_by_line, 1);
}

TEST(SplineOutlines, QuadraticRunsFromTheSecondPointWithTheSlopeOfItsNeighbours) {
    // P0 only sets the slope at P1: (P2 - P0) / 2 = (0.5, 1). The outline closes at P4 = P1.
    const auto s = outlines_of(SplineKind::quadratic, {{-1, -1}, {0, 0}, {0, 1}, {-1, 1}, {0, 0}});
    ASSERT_EQ(s.outlines.size(), 1u);
    EXPECT_EQ(s.closed_by_line, 0);
    const Outline& o = s.outlines[0];
    EXPECT_EQ(o.front().a, (Point2{0, 0}));
    EXPECT_FLOAT_EQ(o.front().tangent_a.x, 0.5f);
    EXPECT_FLOAT_EQ(o.front().tangent_a.y, 1);
    EXPECT_TRUE(passes_through(o, {0, 1}));
    EXPECT_TRUE(passes_through(o, {-1, 1}));
    EXPECT_EQ(o.back().b, (Point2{0, 0}));
}

TEST(SplineOutlines, CubicIsCatmullRomBetweenTheInnerPoints) {
    // Points on a square's corners, the outline from P1 round to P1 again; P0 and the last
    // point set the end slopes. At P1 the slope is (P2 - P0) / 2.
    const std::vector<Point2> p = {{-1, 1}, {-1, -1}, {1, -1}, {1, 1}, {-1, 1}, {-1, -1}, {1, -1}};
    const auto s = outlines_of(SplineKind::cubic, p);
    ASSERT_EQ(s.outlines.size(), 1u);
    const Outline& o = s.outlines[0];
    EXPECT_EQ(o.front().a, p[1]);
    EXPECT_FLOAT_EQ(o.front().tangent_a.x, (p[2].x - p[0].x) / 2);
    EXPECT_FLOAT_EQ(o.front().tangent_a.y, (p[2].y - p[0].y) / 2);
    for (std::size_t i = 2; i <= 5; ++i) EXPECT_TRUE(passes_through(o, p[i])) << i;
}

TEST(SplineOutlines, BezierTakesFourPointsACurve) {
    // One cubic Bezier from (0, 0) to (3, 0) and a straight closing edge back: the curve's
    // midpoint is (P0 + 3 P1 + 3 P2 + P3) / 8 = (1.5, 1.5).
    const auto s = outlines_of(SplineKind::bezier, {{0, 0}, {1, 2}, {2, 2}, {3, 0}});
    ASSERT_EQ(s.outlines.size(), 1u);
    EXPECT_EQ(s.closed_by_line, 1);
    const Outline& o = s.outlines[0];
    EXPECT_EQ(o.front().a, (Point2{0, 0}));
    EXPECT_FLOAT_EQ(o.front().tangent_a.x, 3);  // 3 (P1 - P0)
    EXPECT_FLOAT_EQ(o.front().tangent_a.y, 6);
    EXPECT_TRUE(passes_through(o, {1.5f, 1.5f}));
    EXPECT_TRUE(passes_through(o, {3, 0}));
}

TEST(SplineOutlines, TooFewPointsAreNamed) {
    const std::vector<Point2> two = {{0, 0}, {1, 0}};
    EXPECT_EQ(std::get<std::string>(spline_outlines(SplineKind::linear, two)),
              "a linear spline needs at least 3 points, got 2");
    const std::vector<Point2> six = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}, {2, 2}};
    EXPECT_EQ(std::get<std::string>(spline_outlines(SplineKind::bezier, six)),
              "too few points: the spline's segment from point 5 needs point 8, but there are 6");
    EXPECT_FALSE(spline_kind("bspline"));
    EXPECT_EQ(spline_kind("cubic"), SplineKind::cubic);
}

}  // namespace
}  // namespace glint
