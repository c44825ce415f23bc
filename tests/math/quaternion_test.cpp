#include "glint/math/quaternion.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "glint/math/constants.h"

namespace glint {
namespace {

void expect_near(Vector3 a, Vector3 b, float tol) {
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
    EXPECT_NEAR(a.z, b.z, tol);
}

void expect_near(const Matrix4& a, const Matrix4& b, float tol) {
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) EXPECT_NEAR(a.m[i][j], b.m[i][j], tol) << i << "," << j;
}

// The quaternion of a turn by `degrees` about the unit `axis`, from its definition.
Quaternion axis_angle(Vector3 axis, float degrees) {
    const float half = radians(degrees) / 2;
    return {axis * std::sin(half), std::cos(half)};
}

Vector3 rotate(Quaternion q, Vector3 v) { return Transform(rotation_matrix(q), {})(v); }

TEST(Quaternion, MatchesTheAxisAngleDefinition) {
    // 90 degrees about z: (0, 0, sin 45, cos 45), up to the sign shared by q and -q.
    const Quaternion q = quaternion_from_rotation(Transform::rotate({0, 0, 1}, 90).matrix());
    const float sign = q.w < 0 ? -1.0f : 1.0f;
    EXPECT_NEAR(sign * q.v.x, 0, 1e-7);
    EXPECT_NEAR(sign * q.v.y, 0, 1e-7);
    EXPECT_NEAR(sign * q.v.z, std::sqrt(0.5f), 1e-7);
    EXPECT_NEAR(sign * q.w, std::sqrt(0.5f), 1e-7);
    // And back: the quarter turn about z takes +x to +y.
    expect_near(rotate(axis_angle({0, 0, 1}, 90), {1, 0, 0}), {0, 1, 0}, 1e-7f);
}

TEST(Quaternion, RandomRotationsRoundTripThroughMatrices) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(-1, 1);
    for (int i = 0; i < 1000; ++i) {
        const Vector3 axis{u(rng), u(rng), u(rng) + 0.01f};
        const Transform r = Transform::rotate(axis, 180 * u(rng));
        const Quaternion q = quaternion_from_rotation(r.matrix());
        EXPECT_NEAR(dot(q, q), 1, 1e-6);
        expect_near(rotation_matrix(q), r.matrix(), 2e-6f);
        // The matrix of a quaternion gives the quaternion back, up to sign.
        EXPECT_NEAR(std::abs(dot(quaternion_from_rotation(rotation_matrix(q)), q)), 1, 1e-6);
    }
}

TEST(Quaternion, HalfTurnsUseEachOfShepperdsCases) {
    // Trace -1: w = 0, so the diagonal element that is largest picks x, y or z to divide by.
    for (const Vector3 axis : {Vector3{1, 0, 0}, Vector3{0, 1, 0}, Vector3{0, 0, 1},
                               normalize(Vector3{1, 1, 0}), normalize(Vector3{0, -1, 2})}) {
        const Transform r = Transform::rotate(axis, 180);
        const Quaternion q = quaternion_from_rotation(r.matrix());
        EXPECT_NEAR(q.w, 0, 1e-6);
        EXPECT_NEAR(std::abs(dot(q.v, axis)), 1, 1e-6);
        expect_near(rotation_matrix(q), r.matrix(), 1e-6f);
    }
}

TEST(Quaternion, SlerpHalfwayToAQuarterTurnIsAnEighthTurn) {
    const Quaternion identity;
    const Quaternion quarter = quaternion_from_rotation(Transform::rotate({0, 1, 0}, 90).matrix());
    const Quaternion half = slerp(identity, quarter, 0.5f);
    // 45 degrees about +y takes +x to (cos 45, 0, -sin 45).
    const float c = std::cos(kPi / 4), s = std::sin(kPi / 4);
    expect_near(rotate(half, {1, 0, 0}), {c, 0, -s}, 1e-7f);
    expect_near(rotate(half, {0, 0, 1}), {s, 0, c}, 1e-7f);
    expect_near(rotate(half, {0, 1, 0}), {0, 1, 0}, 1e-7f);
}

TEST(Quaternion, SlerpTakesTheShorterArc) {
    // 350 and 10 degrees about z are 20 degrees apart through 0, not 340 through 180.
    const Quaternion a = axis_angle({0, 0, 1}, 350);
    const Quaternion b = axis_angle({0, 0, 1}, 10);
    EXPECT_LT(dot(a, b), 0);  // the quaternions themselves lie in opposite hemispheres
    expect_near(rotate(slerp(a, b, 0.5f), {1, 0, 0}), {1, 0, 0}, 1e-6f);
    const float quarter = radians(-5);  // a quarter of the way: 355 degrees
    expect_near(rotate(slerp(a, b, 0.25f), {1, 0, 0}), {std::cos(quarter), std::sin(quarter), 0},
                1e-6f);
    EXPECT_NEAR(rotation_angle_between(a, b), radians(20), 1e-6);
}

TEST(Quaternion, SlerpTurnsAtConstantAngularSpeed) {
    const Vector3 axis = normalize(Vector3{1, 2, 3});
    const Quaternion a = axis_angle(normalize(Vector3{-1, 0, 1}), 30);
    const Quaternion b = quaternion_from_rotation(
        (Transform::rotate(axis, 150) * Transform(rotation_matrix(a), {})).matrix());
    EXPECT_NEAR(rotation_angle_between(a, b), radians(150), 1e-5);
    for (const float t : {0.0f, 0.1f, 1 / 3.0f, 0.5f, 0.9f, 1.0f}) {
        const Quaternion q = slerp(a, b, t);
        EXPECT_NEAR(dot(q, q), 1, 1e-6);
        EXPECT_NEAR(rotation_angle_between(a, q), t * radians(150), 1e-5) << t;
        EXPECT_NEAR(rotation_angle_between(q, b), (1 - t) * radians(150), 1e-5) << t;
        // b = turn(150) a, so the orientation at t is turn(150 t) a: one fixed axis.
        const Vector3 v{0.3f, -0.7f, 0.5f};
        expect_near(rotate(q, v), Transform::rotate(axis, 150 * t)(rotate(a, v)), 1e-6f);
    }
    EXPECT_NEAR(std::abs(dot(slerp(a, b, 0), a)), 1, 1e-7);
    EXPECT_NEAR(std::abs(dot(slerp(a, b, 1), b)), 1, 1e-7);
}

TEST(Quaternion, SlerpOfNearlyEqualOrientationsIsFiniteAndBetweenThem) {
    const Quaternion a = axis_angle(normalize(Vector3{1, 1, 1}), 40);
    EXPECT_EQ(rotation_angle_between(a, a), 0);
    const Quaternion same = slerp(a, a, 0.3f);
    EXPECT_NEAR(dot(same, a), 1, 1e-7);
    // 1e-5 degrees apart: well inside the normalised-lerp fall-back.
    const Quaternion b = axis_angle(normalize(Vector3{1, 1, 1}), 40.00001f);
    const Quaternion mid = slerp(a, b, 0.5f);
    EXPECT_TRUE(std::isfinite(mid.w) && is_finite(mid.v));
    EXPECT_NEAR(dot(mid, mid), 1, 1e-7);
    EXPECT_NEAR(dot(mid, a), 1, 1e-7);
    // -a is the same orientation as a.
    EXPECT_NEAR(rotation_angle_between(a, Quaternion{-a.v, -a.w}), 0, 1e-6);
}

}  // namespace
}  // namespace glint
