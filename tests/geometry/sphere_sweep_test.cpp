#include "glint/geometry/sphere_sweep.h"

#include <gtest/gtest.h>

#include <cmath>

namespace glint {
namespace {

SweepPieces pieces_of(SweepSpline spline, const std::vector<SweptSphere>& spheres,
                      float tolerance = 1e-3f) {
    auto made = sweep_pieces(spline, spheres, tolerance);
    EXPECT_TRUE(std::holds_alternative<SweepPieces>(made)) << std::get<std::string>(made);
    return std::get<SweepPieces>(made);
}

// The distance from p to the segment ab.
float distance_to_segment(Point3 p, Point3 a, Point3 b) {
    const Vector3 ab = b - a;
    const float t = std::clamp(dot(p - a, ab) / dot(ab, ab), 0.f, 1.f);
    return length(p - (a + ab * t));
}

TEST(SphereSweep, TheConeTouchesBothSpheres) {
    // Radius 1 at the origin, 0.5 at x = 2: sin(alpha) = 0.25, cos(alpha) = sqrt(15) / 4.
    const auto cone = tangent_cone({{0, 0, 0}, 1}, {{2, 0, 0}, 0.5f});
    ASSERT_TRUE(cone);
    EXPECT_NEAR(cone->base.x, 0.25f, 1e-6f);
    EXPECT_NEAR(cone->base_radius, 0.968246f, 1e-6f);
    EXPECT_NEAR(cone->apex.x, 2.125f, 1e-6f);
    EXPECT_NEAR(cone->apex_radius, 0.484123f, 1e-6f);
    EXPECT_TRUE(cone->capped);
    // The side's line in the x-y plane lies at each sphere's radius from its centre, and each
    // rim on its sphere.
    const Point3 rim_a{cone->base.x, cone->base_radius, 0};
    const Point3 rim_b{cone->apex.x, cone->apex_radius, 0};
    EXPECT_NEAR(length(rim_a - Point3{0, 0, 0}), 1, 1e-6f);
    EXPECT_NEAR(length(rim_b - Point3{2, 0, 0}), 0.5f, 1e-6f);
    const Vector3 side = normalize(rim_b - rim_a);
    const auto off_line = [&](Point3 c) {
        const Vector3 to_c = c - rim_a;
        return length(to_c - side * dot(to_c, side));
    };
    EXPECT_NEAR(off_line({0, 0, 0}), 1, 1e-5f);
    EXPECT_NEAR(off_line({2, 0, 0}), 0.5f, 1e-5f);
}

TEST(SphereSweep, EqualRadiiGiveACylinderBetweenTheCentres) {
    const auto cone = tangent_cone({{0, 0, 0}, 0.5f}, {{0, 0, 3}, 0.5f});
    ASSERT_TRUE(cone);
    EXPECT_EQ(cone->base, (Point3{0, 0, 0}));
    EXPECT_EQ(cone->apex, (Point3{0, 0, 3}));
    EXPECT_EQ(cone->base_radius, 0.5f);
    EXPECT_EQ(cone->apex_radius, 0.5f);
}

TEST(SphereSweep, NoConeWhereOneSphereHoldsTheOther) {
    EXPECT_FALSE(tangent_cone({{0, 0, 0}, 2}, {{1, 0, 0}, 0.5f}));
    EXPECT_FALSE(tangent_cone({{0, 0, 0}, 1}, {{0, 0, 0}, 1}));
}

TEST(SphereSweep, TheSplinesBlendTheirSpheresAsPovRayDoes) {
    const std::vector<SweptSphere> s = {
        {{0, 0, 0}, 1}, {{1, 2, 0}, 2}, {{3, 2, 0}, 1}, {{4, 0, 0}, 3}};
    // B-spline: (P0 + 4 P1 + P2) / 6 at the start, (P1 + 4 P2 + P3) / 6 at the end.
    const SweptSphere b0 = sweep_at(SweepSpline::b_spline, s, 0, 0);
    EXPECT_NEAR(b0.center.x, 7.f / 6, 1e-6f);
    EXPECT_NEAR(b0.center.y, 10.f / 6, 1e-6f);
    EXPECT_NEAR(b0.radius, 10.f / 6, 1e-6f);
    const SweptSphere b1 = sweep_at(SweepSpline::b_spline, s, 0, 1);
    EXPECT_NEAR(b1.center.x, 17.f / 6, 1e-5f);
    EXPECT_NEAR(b1.radius, 9.f / 6, 1e-5f);
    // Catmull-Rom: through P1 and P2, its middle (-P0 + 9 P1 + 9 P2 - P3) / 16.
    const SweptSphere c0 = sweep_at(SweepSpline::cubic, s, 0, 0);
    EXPECT_EQ(c0.center, (Point3{1, 2, 0}));
    EXPECT_EQ(c0.radius, 2);
    const SweptSphere cm = sweep_at(SweepSpline::cubic, s, 0, 0.5f);
    EXPECT_NEAR(cm.center.x, 32.f / 16, 1e-5f);
    EXPECT_NEAR(cm.center.y, 36.f / 16, 1e-5f);
    EXPECT_NEAR(cm.radius, 23.f / 16, 1e-5f);
    const SweptSphere c1 = sweep_at(SweepSpline::cubic, s, 0, 1);
    EXPECT_NEAR(c1.center.x, 3, 1e-5f);
    EXPECT_NEAR(c1.radius, 1, 1e-5f);
    // Linear: straight between two spheres.
    const SweptSphere l = sweep_at(SweepSpline::linear, s, 2, 0.25f);
    EXPECT_NEAR(l.center.x, 3.25f, 1e-6f);
    EXPECT_NEAR(l.center.y, 1.5f, 1e-6f);
    EXPECT_NEAR(l.radius, 1.5f, 1e-6f);
}

TEST(SphereSweep, AStraightSweepIsItsSpheresAndTheConesBetween) {
    const SweepPieces p =
        pieces_of(SweepSpline::linear, {{{0, 0, 0}, 1}, {{0, 3, 0}, 0.5f}, {{2, 3, 0}, 0.5f}});
    ASSERT_EQ(p.spheres.size(), 3u);
    EXPECT_EQ(p.spheres[1].center, (Point3{0, 3, 0}));
    EXPECT_EQ(p.spheres[1].radius, 0.5f);
    EXPECT_EQ(p.cones.size(), 2u);
}

TEST(SphereSweep, ACurvedSweepStaysWithinItsToleranceOfTheCurve) {
    const std::vector<SweptSphere> s = {{{0, 0, 0}, 0.5f},
                                        {{1, 2, 0}, 0.5f},
                                        {{3, 2, 1}, 0.4f},
                                        {{4, 0, 0}, 0.5f},
                                        {{6, 1, 0}, 0.3f}};
    for (const SweepSpline spline : {SweepSpline::b_spline, SweepSpline::cubic}) {
        const SweepPieces coarse = pieces_of(spline, s, 1e-2f);
        const SweepPieces fine = pieces_of(spline, s, 1e-4f);
        EXPECT_GT(fine.spheres.size(), 2 * coarse.spheres.size());
        EXPECT_LE(fine.spheres.size(), 2 * 256 + 1u);
        // Every point of the curve lies near the chain of the joints' centres, within a few
        // times the tolerance of the radius.
        for (std::size_t segment = 0; segment + 3 < s.size(); ++segment) {
            for (int k = 0; k <= 200; ++k) {
                const SweptSphere on = sweep_at(spline, s, segment, float(k) / 200);
                float nearest = kInfinity;
                for (std::size_t i = 0; i + 1 < fine.spheres.size(); ++i)
                    nearest =
                        std::min(nearest, distance_to_segment(on.center, fine.spheres[i].center,
                                                              fine.spheres[i + 1].center));
                EXPECT_LT(nearest, 4 * 1e-4f * 0.3f + 1e-5f) << segment << " " << k;
            }
        }
        // The chain begins and ends where the curve does.
        const SweptSphere start = sweep_at(spline, s, 0, 0);
        EXPECT_EQ(fine.spheres.front().center, start.center);
        const SweptSphere end = sweep_at(spline, s, 1, 1);
        EXPECT_NEAR(length(fine.spheres.back().center - end.center), 0, 1e-5f);
    }
}

TEST(SphereSweep, TooFewSpheresOrARadiusNotAboveZeroIsRefused) {
    auto made =
        sweep_pieces(SweepSpline::b_spline, {{{0, 0, 0}, 1}, {{1, 0, 0}, 1}, {{2, 0, 0}, 1}});
    ASSERT_TRUE(std::holds_alternative<std::string>(made));
    EXPECT_EQ(std::get<std::string>(made), "sphere_sweep b_spline needs at least 4 spheres, got 3");
    made = sweep_pieces(SweepSpline::linear, {{{0, 0, 0}, 1}});
    EXPECT_EQ(std::get<std::string>(made),
              "sphere_sweep linear_spline needs at least 2 spheres, got 1");
    // A Catmull-Rom radius that overshoots below zero between its spheres.
    made = sweep_pieces(SweepSpline::cubic,
                        {{{0, 0, 0}, 10}, {{1, 0, 0}, 0.01f}, {{2, 0, 0}, 0.01f}, {{3, 0, 0}, 10}});
    ASSERT_TRUE(std::holds_alternative<std::string>(made));
    EXPECT_NE(std::get<std::string>(made).find("radius must be > 0 along its path"),
              std::string::npos);
}

}  // namespace
}  // namespace glint
