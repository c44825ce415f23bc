#include "glint/shading/light.h"

#include <gtest/gtest.h>

#include "glint/math/constants.h"
#include "glint/math/interval.h"
#include "glint/sampling/random.h"

namespace glint {
namespace {

TEST(Light, PointLightWithoutAttenuationKeepsItsIntensity) {
    const LightSample s = sample_light(PointLight{{0, 4, 3}, {1, 0.5f, 0.25f}}, {0, 0, 0});
    EXPECT_FLOAT_EQ(s.distance, 5);
    EXPECT_FLOAT_EQ(s.to_light.y, 0.8f);
    EXPECT_FLOAT_EQ(s.to_light.z, 0.6f);
    EXPECT_EQ(s.intensity, (Color{1, 0.5f, 0.25f}));
}

TEST(Light, AttenuationIsOneOverConstantPlusLinearPlusQuadratic) {
    // d = 5: 1 / (1 + 0.1 * 5 + 0.02 * 25) = 1 / 2.
    PointLight light{{0, 4, 3}, {1, 1, 1}, {1, 0.1f, 0.02f}};
    const LightSample s = sample_light(light, {0, 0, 0});
    EXPECT_FLOAT_EQ(s.intensity.r, 0.5f);
}

TEST(Light, DirectionalLightComesFromInfinitelyFarAway) {
    const LightSample s = sample_light(DirectionalLight{{0, -1, 0}, {1, 1, 1}}, {5, 5, 5});
    EXPECT_EQ(s.to_light, (Vector3{0, 1, 0}));
    EXPECT_EQ(s.distance, kInfinity);
}

TEST(Light, SpotLightIsFullInsideDarkOutsideAndSmoothBetween) {
    // Cone of 30 degrees with a 10 degree falloff: full within 20, dark beyond 30, and at 25
    // degrees smoothstep(t) = t^2 (3 - 2t) with t = (cos 25 - cos 30) / (cos 20 - cos 30).
    SpotLight spot;
    spot.position = {0, 0, 0};
    spot.direction = {0, -1, 0};
    spot.cos_cone = std::cos(radians(30));
    spot.cos_falloff = std::cos(radians(20));
    const auto at_angle = [&](float degrees) {
        const float a = radians(degrees);
        return sample_light(spot, {std::sin(a), -std::cos(a), 0}).intensity.r;
    };
    EXPECT_FLOAT_EQ(at_angle(0), 1);
    EXPECT_FLOAT_EQ(at_angle(19), 1);
    EXPECT_EQ(at_angle(31), 0);
    const float t = (std::cos(radians(25)) - std::cos(radians(30))) /
                    (std::cos(radians(20)) - std::cos(radians(30)));
    EXPECT_NEAR(at_angle(25), t * t * (3 - 2 * t), 1e-5);
    EXPECT_NEAR(t, 0.5469, 1e-3);
}

// POV-Ray's tightness 10: cos^10 of the angle from the axis on top of the rim; 0.98481^10 =
// 0.85805 at 10 degrees; at 25, (cos 25)^10 = 0.3739 times the rim's smoothstep of t = 0.5469,
// 0.5702; dark beyond.
TEST(Light, SpotLightTightnessGathersTheLightTowardsItsAxis) {
    SpotLight spot;
    spot.direction = {0, -1, 0};
    spot.cos_cone = std::cos(radians(30));
    spot.cos_falloff = std::cos(radians(20));
    spot.tightness = 10;
    EXPECT_FLOAT_EQ(spot_factor(spot, 1), 1);
    EXPECT_NEAR(spot_factor(spot, std::cos(radians(10))), 0.85805f, 1e-4f);
    EXPECT_NEAR(spot_factor(spot, std::cos(radians(25))), 0.3739f * 0.5702f, 2e-4f);
    EXPECT_EQ(spot_factor(spot, std::cos(radians(31))), 0);
    // Through sample_light as through the emission of particles alike.
    const float a = radians(10);
    EXPECT_NEAR(sample_light(spot, {std::sin(a), -std::cos(a), 0}).intensity.g, 0.85805f, 1e-4f);
}

TEST(Light, AreaLightSeenByWhittedIsAPointLightAtItsCentre) {
    const AreaLight light = *rectangle_light({0, 4, 3}, {2, 0, 0}, {0, 0, 2});
    const LightSample s = sample_light(light, {0, 0, 0});
    EXPECT_FLOAT_EQ(s.distance, 5);
    EXPECT_FLOAT_EQ(s.to_light.y, 0.8f);
    EXPECT_TRUE(is_area_light(light));
    EXPECT_FALSE(is_area_light(PointLight{}));
}

TEST(Light, AreaLightPointsLieOnTheirShapes) {
    const Point3 p{0, 0, 0};
    const AreaLight rectangle = *rectangle_light({0, 4, 0}, {2, 0, 0}, {0, 0, 1});
    const AreaLight disk = disk_light({0, 4, 0}, {0, -1, 0}, 1.5f);
    const AreaLight sphere = sphere_light({0, 4, 0}, 1);
    double mean_x = 0;
    for (int i = 0; i < 2000; ++i) {
        const Point2 u{random_float(i, 0, 0, 2), random_float(i, 0, 1, 2)};
        const LightSample r = sample_light(rectangle, p, u);
        const Point3 q = p + r.to_light * r.distance;
        EXPECT_NEAR(q.y, 4, 1e-5);
        EXPECT_LE(std::abs(q.x), 1 + 1e-5);
        EXPECT_LE(std::abs(q.z), 0.5 + 1e-5);
        mean_x += q.x;
        const LightSample d = sample_light(disk, p, u);
        const Point3 dq = p + d.to_light * d.distance;
        EXPECT_NEAR(dq.y, 4, 1e-5);
        EXPECT_LE(std::hypot(dq.x, dq.z), 1.5 + 1e-5);
        // The sphere's points are on the side facing p: (q - c).(p - c) >= 0.
        const LightSample s = sample_light(sphere, p, u);
        const Point3 sq = p + s.to_light * s.distance;
        EXPECT_NEAR(distance(sq, {0, 4, 0}), 1, 1e-4);
        EXPECT_GE(dot(sq - Point3{0, 4, 0}, p - Point3{0, 4, 0}), -1e-4);
    }
    EXPECT_NEAR(mean_x / 2000, 0, 0.03);  // uniform over the rectangle
}

TEST(Light, AreaLightAttenuatesByTheDistanceToTheDrawnPoint) {
    // A point of the rectangle at (1, 4, 0) (u = (1, 0.5) of sides 2 and 1): d = sqrt(17),
    // 1 / (0 + 0 + d^2) = 1 / 17.
    AreaLight light = *rectangle_light({0, 4, 0}, {2, 0, 0}, {0, 0, 1});
    light.attenuation = {0, 0, 1};
    const LightSample s = sample_light(light, {0, 0, 0}, {0x1.fffffep-1f, 0.5f});
    EXPECT_NEAR(s.distance, std::sqrt(17.0f), 1e-5);
    EXPECT_NEAR(s.intensity.r, 1 / 17.0f, 1e-6);
}

}  // namespace
}  // namespace glint
