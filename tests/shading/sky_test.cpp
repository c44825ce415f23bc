#include "glint/shading/sky.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>

#include "glint/math/constants.h"
#include "glint/sampling/random.h"
#include "sampling/chi_square.h"

namespace glint::sky_test {

constexpr double kPiD = std::numbers::pi;

// A 4 x 2 image whose pixels are all different: pixel (x, y) = (x, y, 1).
SkyImage four_by_two(float rotation_degrees = 0) {
    auto image = std::make_shared<Image>(4, 2);
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 4; ++x) image->at(x, y) = {float(x), float(y), 1};
    return {image, rotation_degrees * kPi / 180, {1, 1, 1}};
}

void expect_color_near(Color a, Color b, float tolerance = 1e-5f) {
    EXPECT_NEAR(a.r, b.r, tolerance);
    EXPECT_NEAR(a.g, b.g, tolerance);
    EXPECT_NEAR(a.b, b.b, tolerance);
}

TEST(Sky, OneColourIsSeenEverywhereAndDrawnFromUniformly) {
    const Sky sky(Color{0.2f, 0.4f, 0.6f});
    expect_color_near(sky.radiance({0, 1, 0}), {0.2f, 0.4f, 0.6f}, 0);
    expect_color_near(sky.radiance({3, -1, 2}), {0.2f, 0.4f, 0.6f}, 0);
    expect_color_near(sky.mean_radiance(), {0.2f, 0.4f, 0.6f}, 0);
    EXPECT_FLOAT_EQ(sky.pdf({1, 0, 0}), 1 / (4 * kPi));
    float pdf = 0;
    const Vector3 w = sky.sample({0.3f, 0.7f}, &pdf);
    EXPECT_NEAR(length(w), 1, 1e-6f);
    EXPECT_FLOAT_EQ(pdf, 1 / (4 * kPi));
    EXPECT_FALSE(sky.is_black());
}

TEST(Sky, ABlackSkyIsNeverDrawnFrom) {
    for (const Sky& sky : {Sky(), Sky(Color{})}) {
        EXPECT_TRUE(sky.is_black());
        float pdf = -1;
        sky.sample({0.5f, 0.5f}, &pdf);
        EXPECT_EQ(pdf, 0);
        EXPECT_EQ(sky.pdf({0, 0, -1}), 0);
    }
    const Sky black_image(SkyImage{std::make_shared<Image>(4, 2), 0, {1, 1, 1}});
    EXPECT_TRUE(black_image.is_black());
    float pdf = -1;
    black_image.sample({0.5f, 0.5f}, &pdf);
    EXPECT_EQ(pdf, 0);
}

// Pixel centres of the 4 x 2 image: columns at longitudes -135, -45, 45 and 135 degrees from
// +z (towards -x, the right of a camera looking along +z), rows at 45 and 135 degrees from
// straight up.
TEST(Sky, TheImageWrapsRoundWithItsMiddleAtPlusZAndItsTopUp) {
    const Sky sky(four_by_two());
    const float h = std::sqrt(0.5f);
    // Up, half way between +z and -x: column 2 (longitude +45), row 0.
    expect_color_near(sky.radiance({-0.5f, h, 0.5f}), {2, 0, 1});
    // Up, between +z and +x: column 1.
    expect_color_near(sky.radiance({0.5f, h, 0.5f}), {1, 0, 1});
    // Down, between -z and -x (longitude 135): column 3, row 1.
    expect_color_near(sky.radiance({-0.5f, -h, -0.5f}), {3, 1, 1});
    // Down, between -z and +x (longitude -135): column 0.
    expect_color_near(sky.radiance({0.5f, -h, -0.5f}), {0, 1, 1});
    // Straight at +z on the horizon: half way between columns 1 and 2 and rows 0 and 1.
    expect_color_near(sky.radiance({0, 0, 1}), {1.5f, 0.5f, 1});
    // Straight at -z, where the image's edges meet: columns 3 and 0 blend across the seam.
    expect_color_near(sky.radiance({0, 0, -1}), {1.5f, 0.5f, 1});
    // Straight up: the top row, between the columns nearest longitude 180 (0 and 3).
    expect_color_near(sky.radiance({0, 1, 0}), {1.5f, 0, 1});
    // Directions of any length.
    expect_color_near(sky.radiance({-5, 5 * h * 2, 5}), {2, 0, 1});
}

TEST(Sky, RotationTurnsTheImageAnticlockwiseSeenFromAbove) {
    const float h = std::sqrt(0.5f);
    // Turned 90 degrees, what was between +z and -x moves between +z and +x, and what was
    // there moves between -z and +x.
    const Sky turned(four_by_two(90));
    expect_color_near(turned.radiance({0.5f, h, 0.5f}), {2, 0, 1});
    expect_color_near(turned.radiance({0.5f, h, -0.5f}), {1, 0, 1});
    EXPECT_NEAR(turned.pdf({0.5f, h, 0.5f}), Sky(four_by_two()).pdf({-0.5f, h, 0.5f}), 1e-6f);
}

TEST(Sky, TheMeanWeighsEachRowByTheSolidAngleItSpans) {
    // Top half 1, bottom half 0: half the sphere.
    auto half = std::make_shared<Image>(8, 4);
    for (int x = 0; x < 8; ++x) half->at(x, 0) = half->at(x, 1) = Color::gray(1);
    EXPECT_NEAR(Sky(SkyImage{half, 0, {1, 1, 1}}).mean_radiance().r, 0.5f, 1e-6f);
    // Only the top row of four: the cap within 45 degrees of up, (1 - cos 45) / 2 of the sphere.
    auto cap = std::make_shared<Image>(8, 4);
    for (int x = 0; x < 8; ++x) cap->at(x, 0) = Color::gray(1);
    EXPECT_NEAR(Sky(SkyImage{cap, 0, {2, 2, 2}}).mean_radiance().r, 2 * (1 - std::sqrt(0.5f)) / 2,
                1e-6f);
}

// A dim sky with a sun: one bright pixel beside a dark one, the rest dim, unevenly.
SkyImage sunny(float rotation = 0.3f) {
    auto image = std::make_shared<Image>(16, 8);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 16; ++x)
            image->at(x, y) = {0.1f + 0.02f * float(x), 0.2f, 0.05f * float(y)};
    image->at(5, 2) = {500, 400, 300};
    image->at(6, 2) = {};
    return {image, rotation, {1, 1, 1}};
}

Vector3 direction(double cos_theta, double phi) {
    const double sin_theta = std::sqrt(std::max(0.0, 1 - cos_theta * cos_theta));
    return {float(sin_theta * std::cos(phi)), float(cos_theta), float(sin_theta * std::sin(phi))};
}

TEST(Sky, DirectionsFollowTheDensityItClaims) {
    // Bins in (theta, phi) whose edges fall on the pixels' (phi from +x towards +z, a quarter
    // turn from the image's longitude): the density is smooth within each, pdf sin(theta).
    const Sky sky(sunny(0));
    const ChiSquareGrid grid{0, kPiD, 32, 0, 2 * kPiD, 64};
    const auto p = bin_probabilities_midpoint(
        grid,
        [&](double theta, double phi) {
            return double(sky.pdf(direction(std::cos(theta), phi))) * std::sin(theta);
        },
        16);
    const auto r = chi_square_test(grid, p, 1'000'000, [&](std::uint64_t i) {
        float pdf = 0;
        const Vector3 w = sky.sample({random_float(i, 0, 0, 3), random_float(i, 0, 1, 3)}, &pdf);
        double phi = std::atan2(double(w.z), double(w.x));
        if (phi < 0) phi += 2 * kPiD;
        return GridPoint{std::acos(std::clamp(double(w.y), -1.0, 1.0)), phi};
    });
    EXPECT_GT(r.p_value, 0.01) << r.description;
}

TEST(Sky, TheDensityIsNeverZeroWhereTheRadianceIsNot) {
    const Sky sky(sunny());
    for (std::uint64_t i = 0; i < 200000; ++i) {
        const Vector3 w =
            direction(2 * random_float(i, 0, 0, 5) - 1, 2 * kPiD * random_float(i, 0, 1, 5));
        if (!is_black(sky.radiance(w))) {
            ASSERT_GT(sky.pdf(w), 0) << i;
        }
    }
}

TEST(Sky, ImportanceSamplesEstimateTheIntegralOfTheRadiance) {
    const Sky sky(sunny());
    // The integral of the filtered radiance over the sphere, by the midpoint rule in
    // (cos theta, phi), which is uniform in solid angle.
    constexpr int kCells = 1024;
    double exact = 0;
    for (int j = 0; j < kCells; ++j)
        for (int i = 0; i < 2 * kCells; ++i)
            exact +=
                sky.radiance(direction(-1 + (j + 0.5) * 2.0 / kCells, (i + 0.5) * kPiD / kCells)).r;
    exact *= (2.0 / kCells) * (kPiD / kCells);
    double estimate = 0;
    constexpr int kSamples = 400000;
    int disagreeing = 0;  // sample() and pdf() on the direction (rounding may cross a pixel edge)
    for (std::uint64_t i = 0; i < kSamples; ++i) {
        float pdf = 0;
        const Vector3 w = sky.sample({random_float(i, 0, 0, 9), random_float(i, 0, 1, 9)}, &pdf);
        if (pdf > 0) estimate += sky.radiance(w).r / pdf;
        if (std::abs(pdf - sky.pdf(w)) > 1e-3f * pdf) ++disagreeing;
    }
    estimate /= kSamples;
    EXPECT_LT(disagreeing, kSamples / 1000);
    EXPECT_NEAR(estimate / exact, 1, 0.01);
    // The mean, from the pixels unfiltered, is close to the filtered radiance's.
    EXPECT_NEAR(sky.mean_radiance().r * 4 * kPiD / exact, 1, 0.02);
}

}  // namespace glint::sky_test
