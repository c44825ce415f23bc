#include "glint/shading/light.h"

#include <gtest/gtest.h>

#include "glint/math/interval.h"

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

}  // namespace
}  // namespace glint
