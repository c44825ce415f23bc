#include "glint/sampling/warp.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <vector>

#include "chi_square.h"
#include "glint/sampling/random.h"

namespace glint::warp_test {
namespace {

constexpr double kPiD = std::numbers::pi;
constexpr std::uint64_t kSamples = 1'000'000;
constexpr float kAlmostOne = 0x1.fffffep-1f;  // the largest float below 1

// Twelve chi-square tests in this file; together they falsely fail with probability 1%.
const double kSignificance = sidak_significance(0.01, 12);

// The i-th uniform pair of a fixed stream: the tests are deterministic.
Point2 uniform_pair(std::uint64_t i, std::uint64_t seed) {
    return {random_float(i, 0, 0, seed), random_float(i, 0, 1, seed)};
}

// The azimuth of d in [0, 2 pi].
double azimuth(Vector3 d) {
    const double phi = std::atan2(double(d.y), double(d.x));
    return phi < 0 ? phi + 2 * kPiD : phi;
}

// (cos theta, phi): solid angle is d(cos theta) d(phi), so a density per steradian is also the
// density in these coordinates.
GridPoint cos_theta_phi(Vector3 d) { return {d.z, azimuth(d)}; }

// (theta, phi), resolving small angles from the direction's x and y rather than its z.
GridPoint theta_phi(Vector3 d) {
    return {std::atan2(std::hypot(double(d.x), double(d.y)), double(d.z)), azimuth(d)};
}

// The corners and middle of [0,1)^2, where warps divide by zero or take logs of zero if careless.
const std::vector<Point2> kCornerCases = {
    {0, 0},    {0, kAlmostOne}, {kAlmostOne, 0},  {kAlmostOne, kAlmostOne}, {0.5f, 0.5f},
    {0, 0.5f}, {0.5f, 0},       {1e-30f, 1e-30f}, {0.5f, kAlmostOne},       {kAlmostOne, 0.5f}};

bool is_finite(Point2 p) { return std::isfinite(p.x) && std::isfinite(p.y); }

// ---- disk ---------------------------------------------------------------------------------------

TEST(UniformDisk, SamplesFollowTheirDensity) {
    const ChiSquareGrid grid{-1, 1, 20, -1, 1, 20};
    const auto probabilities = bin_probabilities_midpoint(
        grid, [](double x, double y) { return x * x + y * y < 1 ? 1 / kPiD : 0.0; });
    const auto r = chi_square_test(grid, probabilities, kSamples, [](std::uint64_t i) {
        const Point2 p = sample_uniform_disk(uniform_pair(i, 1));
        return GridPoint{p.x, p.y};
    });
    EXPECT_GT(r.p_value, kSignificance) << r.description;
}

TEST(UniformDisk, ConcentricMapWorkedExamples) {
    // u = (0.75, 0.5): (a, b) = (0.5, 0), radius 0.5 on +x; u = (0.5, 0.75) likewise on +y.
    const Point2 p = sample_uniform_disk({0.75f, 0.5f});
    EXPECT_NEAR(p.x, 0.5f, 1e-6f);
    EXPECT_NEAR(p.y, 0.0f, 1e-6f);
    const Point2 q = sample_uniform_disk({0.5f, 0.75f});
    EXPECT_NEAR(q.x, 0.0f, 1e-6f);
    EXPECT_NEAR(q.y, 0.5f, 1e-6f);
    // The square's centre is the disk's; the corner u = (0, 0) is the rim at 225 degrees.
    EXPECT_EQ(sample_uniform_disk({0.5f, 0.5f}), (Point2{0, 0}));
    const Point2 c = sample_uniform_disk({0, 0});
    EXPECT_NEAR(c.x, -std::sqrt(0.5f), 1e-6f);
    EXPECT_NEAR(c.y, -std::sqrt(0.5f), 1e-6f);
    EXPECT_FLOAT_EQ(uniform_disk_pdf(), 1 / kPi);
}

TEST(UniformDisk, PolynomialTrigonometryMatchesTheMapInDouble) {
    // The map computes its angle's sine and cosine by polynomials; every point of a 401 x 401
    // grid over the square, the edges included, within two ulps of 1 of the map in double.
    for (int i = 0; i <= 400; ++i)
        for (int j = 0; j <= 400; ++j) {
            const float ux = std::min(float(i) / 400, 0x1.fffffep-1f);
            const float uy = std::min(float(j) / 400, 0x1.fffffep-1f);
            const double a = 2.0 * ux - 1, b = 2.0 * uy - 1;
            double r = 0, phi = 0;
            if (std::abs(a) > std::abs(b)) {
                r = a;
                phi = kPiD / 4 * (b / a);
            } else if (b != 0) {
                r = b;
                phi = kPiD / 2 - kPiD / 4 * (a / b);
            }
            const Point2 p = sample_uniform_disk({ux, uy});
            ASSERT_NEAR(p.x, r * std::cos(phi), 2.4e-7) << ux << ", " << uy;
            ASSERT_NEAR(p.y, r * std::sin(phi), 2.4e-7) << ux << ", " << uy;
        }
}

TEST(UniformDisk, SamplesLieInTheDiskAndAreFiniteAtTheCorners) {
    for (Point2 u : kCornerCases) {
        const Point2 p = sample_uniform_disk(u);
        ASSERT_TRUE(is_finite(p)) << u.x << ", " << u.y;
        EXPECT_LE(p.x * p.x + p.y * p.y, 1 + 1e-6f);
    }
    for (std::uint64_t i = 0; i < 10000; ++i) {
        const Point2 p = sample_uniform_disk(uniform_pair(i, 2));
        ASSERT_LE(p.x * p.x + p.y * p.y, 1 + 1e-6f);
    }
}

// ---- regular polygon -------------------------------------------------------------------------

// A regular polygon's vertices, in double, counter-clockwise.
struct Polygon {
    std::vector<double> x, y;

    Polygon(int sides, double rotation) {
        for (int k = 0; k < sides; ++k) {
            x.push_back(std::cos(rotation + 2 * kPiD * k / sides));
            y.push_back(std::sin(rotation + 2 * kPiD * k / sides));
        }
    }

    // Inside when on the left of every edge.
    bool contains(double px, double py) const {
        const std::size_t n = x.size();
        for (std::size_t k = 0; k < n; ++k) {
            const std::size_t l = (k + 1) % n;
            if ((x[l] - x[k]) * (py - y[k]) - (y[l] - y[k]) * (px - x[k]) < 0) return false;
        }
        return true;
    }
};

void expect_polygon_samples_follow_density(int sides, float rotation, std::uint64_t seed) {
    const ChiSquareGrid grid{-1, 1, 20, -1, 1, 20};
    // The area of n triangles with two unit sides at 2 pi / n, in double.
    const double area = 0.5 * sides * std::sin(2 * kPiD / sides);
    const Polygon polygon(sides, rotation);
    const auto probabilities = bin_probabilities_midpoint(
        grid, [&](double x, double y) { return polygon.contains(x, y) ? 1 / area : 0.0; });
    const auto r = chi_square_test(grid, probabilities, kSamples, [&](std::uint64_t i) {
        const Point2 p = sample_regular_polygon(uniform_pair(i, seed), sides, rotation);
        return GridPoint{p.x, p.y};
    });
    EXPECT_GT(r.p_value, kSignificance) << sides << " sides: " << r.description;
}

TEST(RegularPolygon, PentagonSamplesFollowTheirDensity) {
    expect_polygon_samples_follow_density(5, 0, 3);
}

TEST(RegularPolygon, RotatedHexagonSamplesFollowTheirDensity) {
    expect_polygon_samples_follow_density(6, 0.3f, 4);
}

TEST(RegularPolygon, AreaWorkedNumbers) {
    EXPECT_NEAR(regular_polygon_area(3), 3 * std::sqrt(3.0f) / 4, 1e-6f);  // 1.299
    EXPECT_NEAR(regular_polygon_area(4), 2.0f, 1e-6f);                     // square of side sqrt 2
    EXPECT_NEAR(regular_polygon_area(6), 3 * std::sqrt(3.0f) / 2, 1e-6f);  // six unit triangles
    EXPECT_NEAR(regular_polygon_area(1000), kPi, 1e-4f);                   // nearly the disk
}

TEST(RegularPolygon, SamplesLieInsideAndUxPicksTheWedge) {
    const int sides = 5;
    const float rotation = 0.7f;
    const Polygon polygon(sides, rotation);
    for (std::uint64_t i = 0; i < 10000; ++i) {
        const Point2 u = uniform_pair(i, 5);
        const Point2 p = sample_regular_polygon(u, sides, rotation);
        // Shrunk by 1e-5 towards the centre so that rounding on an edge does not count.
        ASSERT_TRUE(polygon.contains(p.x * (1 - 1e-5), p.y * (1 - 1e-5))) << p.x << ", " << p.y;
        // Wedge k spans angles rotation + [k, k+1) * 72 degrees.
        const int k = std::min(int(u.x * sides), sides - 1);
        const double from_wedge_centre = std::remainder(
            std::atan2(double(p.y), double(p.x)) - rotation - (k + 0.5) * 2 * kPiD / sides,
            2 * kPiD);
        ASSERT_LE(std::abs(from_wedge_centre), kPiD / sides + 1e-4) << i;
    }
}

TEST(RegularPolygon, FiniteAndInsideAtTheCorners) {
    for (int sides : {3, 5, 6, 8, 64}) {
        for (Point2 u : kCornerCases) {
            const Point2 p = sample_regular_polygon(u, sides, 0.25f);
            ASSERT_TRUE(is_finite(p)) << sides << " sides at " << u.x << ", " << u.y;
            EXPECT_LE(p.x * p.x + p.y * p.y, 1 + 1e-5f);
        }
    }
    // u = (0, 0): the first wedge, barycentrics (0, 0, 1), its second vertex, at 0.25 + 60 deg.
    const Point2 c = sample_regular_polygon({0, 0}, 6, 0.25f);
    EXPECT_NEAR(c.x, std::cos(0.25f + kPi / 3), 1e-6f);
    EXPECT_NEAR(c.y, std::sin(0.25f + kPi / 3), 1e-6f);
}

// ---- triangle -------------------------------------------------------------------------------

TEST(UniformTriangle, SamplesFollowTheirDensity) {
    // (s, t) = (b0, b1 / (1 - b0)) maps the triangle onto the unit square with Jacobian
    // 1 - s, so the uniform density 2 becomes 2 (1 - s): smooth, and t <= 1 checks b0 + b1 <= 1.
    const ChiSquareGrid grid{0, 1, 20, 0, 1, 20};
    const auto probabilities =
        bin_probabilities_simpson(grid, [](double s, double) { return 2 * (1 - s); });
    const auto r = chi_square_test(grid, probabilities, kSamples, [](std::uint64_t i) {
        const Point2 b = sample_uniform_triangle(uniform_pair(i, 6));
        return GridPoint{b.x, b.y / (1 - double(b.x))};
    });
    EXPECT_GT(r.p_value, kSignificance) << r.description;
}

TEST(UniformTriangle, WorkedExamplesOfBothHalves) {
    // u.x < u.y: b0 = u.x / 2, b1 = u.y - b0; otherwise b1 = u.y / 2, b0 = u.x - b1.
    EXPECT_EQ(sample_uniform_triangle({0.25f, 0.75f}), (Point2{0.125f, 0.625f}));
    EXPECT_EQ(sample_uniform_triangle({0.75f, 0.25f}), (Point2{0.625f, 0.125f}));
    EXPECT_EQ(sample_uniform_triangle({0, 0}), (Point2{0, 0}));
}

TEST(UniformTriangle, BarycentricsStayInTheTriangle) {
    for (Point2 u : kCornerCases) {
        const Point2 b = sample_uniform_triangle(u);
        EXPECT_GE(b.x, 0);
        EXPECT_GE(b.y, 0);
        EXPECT_LE(b.x + b.y, 1);
    }
    for (std::uint64_t i = 0; i < 10000; ++i) {
        const Point2 b = sample_uniform_triangle(uniform_pair(i, 7));
        ASSERT_GE(b.x, 0);
        ASSERT_GE(b.y, 0);
        ASSERT_LE(b.x + b.y, 1);
    }
}

// ---- sphere and cone ------------------------------------------------------------------------

TEST(UniformSphere, SamplesFollowTheirDensity) {
    const ChiSquareGrid grid{-1, 1, 20, 0, 2 * kPiD, 40};
    const auto probabilities =
        bin_probabilities_simpson(grid, [](double, double) { return 1 / (4 * kPiD); });
    const auto r = chi_square_test(grid, probabilities, kSamples, [](std::uint64_t i) {
        return cos_theta_phi(sample_uniform_sphere(uniform_pair(i, 8)));
    });
    EXPECT_GT(r.p_value, kSignificance) << r.description;
}

TEST(UniformSphere, WorkedExamplesAndUnitLength) {
    EXPECT_EQ(sample_uniform_sphere({0, 0}), Vector3(0, 0, 1));  // the north pole
    const Vector3 equator = sample_uniform_sphere({0.5f, 0.25f});
    EXPECT_NEAR(equator.x, 0, 1e-6f);
    EXPECT_NEAR(equator.y, 1, 1e-6f);
    EXPECT_NEAR(equator.z, 0, 1e-6f);
    EXPECT_FLOAT_EQ(uniform_sphere_pdf(), 0.0795774715f);  // 1 / (4 pi)
    for (Point2 u : kCornerCases) {
        const Vector3 d = sample_uniform_sphere(u);
        ASSERT_TRUE(is_finite(d));
        EXPECT_NEAR(length(d), 1, 1e-6f);
    }
}

void expect_cone_samples_follow_density(float cos_max, std::uint64_t seed) {
    // The grid starts at the float cos_max the warp sees.
    const double c = cos_max;
    const ChiSquareGrid grid{c, 1, 20, 0, 2 * kPiD, 40};
    const auto probabilities =
        bin_probabilities_simpson(grid, [&](double, double) { return 1 / (2 * kPiD * (1 - c)); });
    const auto r = chi_square_test(grid, probabilities, kSamples, [&](std::uint64_t i) {
        return cos_theta_phi(sample_uniform_cone(uniform_pair(i, seed), cos_max));
    });
    EXPECT_GT(r.p_value, kSignificance) << "cos_max " << cos_max << ": " << r.description;
}

TEST(UniformCone, NarrowConeSamplesFollowTheirDensity) {
    expect_cone_samples_follow_density(0.9f, 9);
}

TEST(UniformCone, ConeWiderThanAHemisphereSamplesFollowTheirDensity) {
    expect_cone_samples_follow_density(-0.5f, 10);
}

TEST(UniformCone, PdfWorkedNumbersAndSamplesInsideTheCone) {
    EXPECT_FLOAT_EQ(uniform_cone_pdf(0), 1 / (2 * kPi));   // the hemisphere
    EXPECT_FLOAT_EQ(uniform_cone_pdf(-1), 1 / (4 * kPi));  // the sphere
    EXPECT_NEAR(uniform_cone_pdf(0.9f), 1 / (0.2 * kPiD), 1e-6 / (0.2 * kPiD));
    for (float cos_max : {-1.0f, -0.5f, 0.0f, 0.9f, 0.9999999f}) {
        for (Point2 u : kCornerCases) {
            const Vector3 d = sample_uniform_cone(u, cos_max);
            ASSERT_TRUE(is_finite(d));
            EXPECT_NEAR(length(d), 1, 1e-6f);
            EXPECT_GE(d.z, cos_max - 1e-6f);
        }
    }
    // u.x = 1/2 of a cone of half-angle 60 degrees: cos(theta) = 1 - (1 - 0.5) / 2 = 0.75.
    EXPECT_NEAR(sample_uniform_cone({0.5f, 0.3f}, 0.5f).z, 0.75f, 1e-6f);
}

TEST(UniformCone, TinyConeKeepsItsSine) {
    // Half-angle 1e-3 rad: 1 - cos_max = 5e-7 (as the float cos_max has it); at u.x = 1/4
    // the sine is sqrt(2 * 1.25e-7) to first order, which 1 - cos^2 in float would lose.
    const float cos_max = std::cos(1e-3f);
    const double one_minus_cos = 0.25 * (1 - double(cos_max));
    const double expected_sine = std::sqrt(one_minus_cos * (2 - one_minus_cos));
    const Vector3 d = sample_uniform_cone({0.25f, 0}, cos_max);
    EXPECT_NEAR(std::hypot(d.x, d.y), expected_sine, 1e-4 * expected_sine);
}

// ---- Phong lobe -------------------------------------------------------------------------------

// The lobe's density in (theta, phi): per steradian times sin(theta), in double.
double phong_density_theta_phi(double theta, double exponent) {
    return (exponent + 1) / (2 * kPiD) * std::pow(std::cos(theta), exponent) * std::sin(theta);
}

// Samples with `sampled_exponent` tested against the density of `tested_exponent`, over theta in
// [0, theta_max] (the lobe's mass beyond must be negligible).
ChiSquareResult phong_chi_square(float sampled_exponent, double tested_exponent, double theta_max,
                                 std::uint64_t seed) {
    const ChiSquareGrid grid{0, theta_max, 20, 0, 2 * kPiD, 40};
    const auto probabilities = bin_probabilities_simpson(grid, [&](double theta, double) {
        return phong_density_theta_phi(theta, tested_exponent);
    });
    return chi_square_test(grid, probabilities, kSamples, [&](std::uint64_t i) {
        return theta_phi(sample_phong_lobe(uniform_pair(i, seed), sampled_exponent));
    });
}

TEST(PhongLobe, ExponentZeroIsTheUniformHemisphere) {
    const auto r = phong_chi_square(0, 0, kPiD / 2, 11);
    EXPECT_GT(r.p_value, kSignificance) << r.description;
}

TEST(PhongLobe, ExponentOneSamplesFollowTheirDensity) {
    const auto r = phong_chi_square(1, 1, kPiD / 2, 12);
    EXPECT_GT(r.p_value, kSignificance) << r.description;
}

TEST(PhongLobe, ExponentFiftySamplesFollowTheirDensity) {
    const auto r = phong_chi_square(50, 50, kPiD / 2, 13);
    EXPECT_GT(r.p_value, kSignificance) << r.description;
}

TEST(PhongLobe, ExponentOneMillionSamplesFollowTheirDensity) {
    // The lobe's width is about 1/sqrt(n) = 1e-3 rad; beyond 0.01 rad lies e^-50 of its mass.
    const auto r = phong_chi_square(1e6f, 1e6, 0.01, 14);
    EXPECT_GT(r.p_value, kSignificance) << r.description;
}

TEST(PhongLobe, ChiSquareRejectsTheWrongExponent) {
    // The helper has power: exponent 10 samples do not pass for exponent 12's density.
    const auto r = phong_chi_square(10, 12, kPiD / 2, 15);
    EXPECT_LT(r.p_value, kSignificance) << r.description;
    EXPECT_GT(r.statistic, 10 * r.dof) << r.description;
}

TEST(PhongLobe, PdfWorkedNumbers) {
    EXPECT_FLOAT_EQ(phong_lobe_pdf(1, 10), 11 / (2 * kPi));
    EXPECT_FLOAT_EQ(phong_lobe_pdf(0.5f, 2), 3 / (2 * kPi) * 0.25f);
    EXPECT_FLOAT_EQ(phong_lobe_pdf(0.3f, 0), 1 / (2 * kPi));  // the uniform hemisphere
    EXPECT_EQ(phong_lobe_pdf(-0.1f, 10), 0);                  // below the horizon
    EXPECT_EQ(phong_lobe_pdf(-1, 0), 0);
    EXPECT_FLOAT_EQ(phong_lobe_pdf(1, 1e6f), (1e6f + 1) / (2 * kPi));
}

TEST(PhongLobe, PdfIntegratesToOneOverTheHemisphere) {
    for (float n : {0.0f, 1.0f, 10.0f, 50.0f, 1e3f}) {
        // 2 pi * integral over theta of pdf(cos theta) sin theta, up to where the lobe has died.
        const double theta_cut = std::min(kPiD / 2, 12 / std::sqrt(double(n) + 1));
        const double integral =
            2 * kPiD *
            adaptive_simpson(
                [&](double theta) {
                    return phong_lobe_pdf(float(std::cos(theta)), n) * std::sin(theta);
                },
                0, theta_cut, 1e-9);
        EXPECT_NEAR(integral, 1, 1e-4) << "exponent " << n;
    }
}

TEST(PhongLobe, CosineFollowsTheInverseCdf) {
    // cos(alpha) = (1 - u.x)^(1/(n+1)): u.x = 0.5, n = 1 gives sqrt(0.5).
    EXPECT_NEAR(sample_phong_lobe({0.5f, 0}, 1).z, std::sqrt(0.5f), 1e-6f);
    // n = 0: cos(alpha) = 1 - u.x, the uniform hemisphere's cos.
    EXPECT_NEAR(sample_phong_lobe({0.3f, 0.1f}, 0).z, 0.7f, 1e-6f);
    // u.x = 0 is the lobe's axis, not the horizon.
    EXPECT_EQ(sample_phong_lobe({0, 0.1f}, 5).z, 1);
    // Azimuth 2 pi u.y: u.y = 1/4 points the lobe's tilt along +y.
    const Vector3 d = sample_phong_lobe({0.5f, 0.25f}, 1);
    EXPECT_NEAR(d.x, 0, 1e-6f);
    EXPECT_NEAR(d.y, std::sqrt(0.5f), 1e-6f);
}

TEST(PhongLobe, HugeExponentKeepsItsSine) {
    // 1 - u.x = v near e^-1, n = 1e6: cos = v^(1/(n+1)), 1 - cos = -expm1(log(v)/(n+1)),
    // computed in double; 1 - cos^2 in float would keep one or two digits of it.
    const double n = 1e6;
    const float ux = float(1 - std::exp(-1.0));
    const double v = 1 - double(ux);
    const double one_minus_cos = -std::expm1(std::log(v) / (n + 1));
    const double expected_sine = std::sqrt(one_minus_cos * (2 - one_minus_cos));  // ~1.414e-3
    const Vector3 d = sample_phong_lobe({ux, 0}, float(n));
    EXPECT_NEAR(std::hypot(d.x, d.y), expected_sine, 1e-5 * expected_sine);
    EXPECT_NEAR(length(d), 1, 1e-6f);
}

TEST(PhongLobe, FiniteUnitAndAboveTheHorizonAtTheCorners) {
    for (float n : {0.0f, 1.0f, 50.0f, 1e6f, 1e30f}) {
        for (Point2 u : kCornerCases) {
            const Vector3 d = sample_phong_lobe(u, n);
            ASSERT_TRUE(is_finite(d)) << n << " at " << u.x << ", " << u.y;
            EXPECT_NEAR(length(d), 1, 1e-6f);
            EXPECT_GE(d.z, 0);
            // Every sample is one the pdf can weight: finite and positive.
            const float pdf = phong_lobe_pdf(d.z, n);
            EXPECT_TRUE(std::isfinite(pdf));
            EXPECT_GT(pdf, 0) << n << " at " << u.x << ", " << u.y;
        }
    }
}

// ---- frames -----------------------------------------------------------------------------------

TEST(FromFrame, MapsZToTheAxisAndStaysRightHandedAndOrthonormal) {
    const Vector3 axes[] = {normalize(Vector3(1, 2, 3)), Vector3(0, 0, 1), Vector3(0, 0, -1),
                            normalize(Vector3(-0.3f, 0.1f, -2)), Vector3(1, 0, 0)};
    for (Vector3 axis : axes) {
        const Vector3 x = from_frame({1, 0, 0}, axis), y = from_frame({0, 1, 0}, axis);
        const Vector3 z = from_frame({0, 0, 1}, axis);
        EXPECT_NEAR(length(z - axis), 0, 1e-6f);
        EXPECT_NEAR(length(x), 1, 1e-6f);
        EXPECT_NEAR(length(y), 1, 1e-6f);
        EXPECT_NEAR(dot(x, y), 0, 1e-6f);
        EXPECT_NEAR(dot(x, axis), 0, 1e-6f);
        EXPECT_NEAR(length(cross(x, y) - axis), 0, 1e-5f);  // right-handed
        // Angles to the axis survive: a lobe sample keeps its cosine.
        const Vector3 local = sample_phong_lobe({0.3f, 0.8f}, 20);
        EXPECT_NEAR(dot(from_frame(local, axis), axis), local.z, 1e-5f);
    }
}

// ---- wavelengths -----------------------------------------------------------------------------

// The density, written again in double from its definition: proportional to
// 1 / cosh^2(0.0072 (lambda - 538)), normalised by the tanh antiderivative over [360, 830].
double wavelength_density(double lambda) {
    const double a = 0.0072;
    const double norm = (std::tanh(a * (830 - 538)) - std::tanh(a * (360 - 538))) / a;
    const double c = std::cosh(a * (lambda - 538));
    return 1 / (norm * c * c);
}

TEST(VisibleWavelength, SamplesFollowTheirDensity) {
    const ChiSquareGrid grid{360, 830, 100, 0, 1, 1};
    const auto probabilities = bin_probabilities_simpson(
        grid, [](double lambda, double) { return wavelength_density(lambda); });
    const auto r = chi_square_test(grid, probabilities, kSamples, [](std::uint64_t i) {
        return GridPoint{sample_visible_wavelength(random_float(i, 0, 0, 16)), 0.5};
    });
    EXPECT_GT(r.p_value, kSignificance) << r.description;
}

TEST(VisibleWavelength, PdfMatchesItsDefinitionAndIntegratesToOne) {
    for (double lambda : {360.0, 450.0, 538.0, 600.0, 700.0, 830.0}) {
        EXPECT_NEAR(visible_wavelength_pdf(float(lambda)), wavelength_density(lambda),
                    1e-6 * wavelength_density(lambda))
            << lambda;
    }
    EXPECT_NEAR(visible_wavelength_pdf(538), 0.0039398, 1e-7);  // the peak
    const double integral = adaptive_simpson(
        [](double lambda) { return double(visible_wavelength_pdf(float(lambda))); }, 360, 830,
        1e-9);
    EXPECT_NEAR(integral, 1, 1e-5);
    EXPECT_EQ(visible_wavelength_pdf(359.9f), 0);
    EXPECT_EQ(visible_wavelength_pdf(830.1f), 0);
    EXPECT_EQ(visible_wavelength_pdf(-1), 0);
    EXPECT_EQ(visible_wavelength_pdf(std::nanf("")), 0);
}

TEST(VisibleWavelength, EndsMedianAndMonotonicity) {
    EXPECT_NEAR(sample_visible_wavelength(0), 360, 1e-3);
    EXPECT_NEAR(sample_visible_wavelength(kAlmostOne), 830, 1e-2);
    // The median: 538 + atanh((tanh(-1.2816) + tanh(2.1024)) / 2) / 0.0072 = 545.903 nm.
    const float median = sample_visible_wavelength(0.5f);
    EXPECT_NEAR(median, 545.903, 1e-2);
    const double below = adaptive_simpson(wavelength_density, 360, median, 1e-10);
    EXPECT_NEAR(below, 0.5, 1e-5);
    float previous = 0;
    for (int i = 0; i <= 1000; ++i) {
        const float lambda = sample_visible_wavelength(std::min(i / 1000.0f, kAlmostOne));
        ASSERT_GE(lambda, previous);
        ASSERT_GE(lambda, 360);
        ASSERT_LE(lambda, 830);
        previous = lambda;
    }
}

}  // namespace
}  // namespace glint::warp_test
