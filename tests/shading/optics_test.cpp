#include "glint/shading/optics.h"

#include <gtest/gtest.h>

#include <cmath>

#include "glint/math/constants.h"

namespace glint::optics_test {
namespace {

void expect_near(Vector3 a, Vector3 b, float tol = 1e-5f) {
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
    EXPECT_NEAR(a.z, b.z, tol);
}

const Normal3 kUp{0, 1, 0};

Vector3 incoming_at(float degrees_from_normal) {
    return {std::sin(radians(degrees_from_normal)), -std::cos(radians(degrees_from_normal)), 0};
}

TEST(Optics, ReflectionMirrorsAboutTheNormal) {
    // R = D - 2 (D.N) N: (1 -1 0) -> (1 1 0).
    expect_near(reflect({1, -1, 0}, kUp), {1, 1, 0});
    expect_near(reflect({0, -1, 0}, kUp), {0, 1, 0});
    // Reflection keeps the length and the tangential part.
    const Vector3 d = normalize(Vector3{0.3f, -0.8f, 0.5f});
    EXPECT_NEAR(length(reflect(d, kUp)), 1, 1e-6);
}

TEST(Optics, RefractionIntoGlassFollowsSnellsLaw) {
    // 45 degrees from air into glass (n = 1.5): sin(theta_t) = sin 45 / 1.5 = 0.4714.
    const auto t = refract(incoming_at(45), kUp, 1 / 1.5f);
    ASSERT_TRUE(t);
    expect_near(*t, {0.471405f, -0.881917f, 0});
    EXPECT_NEAR(length(*t), 1, 1e-6);
}

TEST(Optics, NormalIncidencePassesStraightThrough) {
    const auto t = refract({0, -1, 0}, kUp, 1 / 1.33f);
    ASSERT_TRUE(t);
    expect_near(*t, {0, -1, 0});
}

TEST(Optics, TotalInternalReflectionPastTheCriticalAngle) {
    // Glass to air: the critical angle is asin(1 / 1.5) = 41.81 degrees.
    const float eta = 1.5f;
    const auto below = refract(incoming_at(41.5f), kUp, eta);
    ASSERT_TRUE(below);
    EXPECT_NEAR(std::asin(below->x), radians(83.68f), 2e-3);  // 1.5 sin 41.5 = 0.99393
    const auto at = refract(incoming_at(41.8103f), kUp, eta);
    ASSERT_TRUE(at);
    EXPECT_NEAR(at->y, 0, 2e-3);  // grazing: along the surface
    EXPECT_FALSE(refract(incoming_at(42), kUp, eta));
    EXPECT_FALSE(refract(incoming_at(80), kUp, eta));
}

}  // namespace
}  // namespace glint::optics_test
