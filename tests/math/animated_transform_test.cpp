#include "glint/math/animated_transform.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

#include "glint/math/constants.h"

namespace glint::animated_transform_test {
namespace {

void expect_near(Point3 a, Point3 b, float tol) {
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
    EXPECT_NEAR(a.z, b.z, tol);
}

void expect_near(const Matrix4& a, const Matrix4& b, float tol) {
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) EXPECT_NEAR(a.m[i][j], b.m[i][j], tol) << i << "," << j;
}

// x += k y: a shear, whose polar decomposition has a non-diagonal stretch.
Transform shear(float k) {
    Matrix4 m = Matrix4::identity();
    m.m[0][1] = k;
    return *Transform::from_matrix(m);
}

Point3 corner(const Bounds3& b, int i) {
    return {i & 1 ? b.max.x : b.min.x, i & 2 ? b.max.y : b.min.y, i & 4 ? b.max.z : b.min.z};
}

void expect_same(const Bounds3& a, const Bounds3& b) {
    EXPECT_EQ(a.min, b.min);
    EXPECT_EQ(a.max, b.max);
}

bool contains(const Bounds3& outer, const Bounds3& inner) {
    return outer.contains(inner.min) && outer.contains(inner.max);
}

TEST(Decompose, SeparatesTranslationRotationAndScale) {
    const Transform m = Transform::translate({1, 2, 3}) * Transform::rotate({0, 0, 1}, 30) *
                        Transform::scale(2, 3, 4);
    const auto parts = decompose(m.matrix());
    ASSERT_TRUE(parts);
    EXPECT_EQ(parts->translation, (Vector3{1, 2, 3}));
    expect_near(rotation_matrix(parts->rotation), Transform::rotate({0, 0, 1}, 30).matrix(), 1e-6f);
    expect_near(parts->stretch, Transform::scale(2, 3, 4).matrix(), 1e-5f);
}

TEST(Decompose, PutsAMirrorInTheStretchAndKeepsTheRotationProper) {
    // diag(-1, 1, 1) = (half turn about x) * (-identity): the rotation is diag(1, -1, -1).
    const auto parts = decompose(Transform::scale(-1, 1, 1).matrix());
    ASSERT_TRUE(parts);
    expect_near(rotation_matrix(parts->rotation), Transform::rotate({1, 0, 0}, 180).matrix(),
                1e-6f);
    expect_near(parts->stretch, Transform::scale(-1, -1, -1).matrix(), 1e-6f);
}

TEST(Decompose, RecomposesRandomAffineMatrices) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(-1, 1);
    for (int i = 0; i < 500; ++i) {
        const float mirror = i % 2 ? -1.0f : 1.0f;
        Transform m = Transform::translate({3 * u(rng), 3 * u(rng), 3 * u(rng)}) *
                      Transform::rotate({u(rng), u(rng), u(rng) + 0.01f}, 180 * u(rng)) *
                      Transform::scale(mirror * (1.6f + 1.4f * u(rng)), 1.6f + 1.4f * u(rng),
                                       1.6f + 1.4f * u(rng));
        if (i % 3 == 0) m = m * shear(u(rng));
        const auto parts = decompose(m.matrix());
        ASSERT_TRUE(parts);
        expect_near(recompose(*parts), m.matrix(), 1e-5f);
        // A proper rotation; a symmetric stretch whose sign carries the mirror.
        EXPECT_NEAR(dot(parts->rotation, parts->rotation), 1, 1e-6);
        const auto& s = parts->stretch.m;
        EXPECT_NEAR(s[0][1], s[1][0], 1e-6);
        EXPECT_NEAR(s[0][2], s[2][0], 1e-6);
        EXPECT_NEAR(s[1][2], s[2][1], 1e-6);
        EXPECT_EQ(s[0][0] > 0, mirror > 0);
    }
}

TEST(Decompose, ConvergesForStronglyScaledMatrices) {
    const Transform m = Transform::rotate({1, 2, 3}, 70) * Transform::scale(1000, 0.001f, 1);
    const auto parts = decompose(m.matrix());
    ASSERT_TRUE(parts);
    expect_near(rotation_matrix(parts->rotation), Transform::rotate({1, 2, 3}, 70).matrix(), 1e-6f);
    expect_near(recompose(*parts), m.matrix(), 1e-4f);  // entries up to 1000
}

TEST(Decompose, RejectsSingularProjectiveAndNonFiniteMatrices) {
    Matrix4 flat = Matrix4::identity();
    flat.m[1][1] = 0;
    EXPECT_FALSE(decompose(flat));
    Matrix4 projective = Matrix4::identity();
    projective.m[3][2] = 1;
    EXPECT_FALSE(decompose(projective));
    Matrix4 nan = Matrix4::identity();
    nan.m[0][3] = std::numeric_limits<float>::quiet_NaN();
    EXPECT_FALSE(decompose(nan));
}

TEST(AnimatedTransform, ReturnsEachKeyframeAtItsTimeAndClampsOutside) {
    const Transform a = Transform::translate({1, 0, 0});
    const Transform b = Transform::rotate({0, 1, 0}, 60) * Transform::scale(1, 2, 1);
    const Transform c = Transform::translate({0, 0, 5}) * Transform::scale(0.5f, 0.5f, 0.5f);
    const AnimatedTransform animated({{0, a}, {1, b}, {3, c}});
    EXPECT_EQ(animated.at(0), a);
    EXPECT_EQ(animated.at(1), b);
    EXPECT_EQ(animated.at(3), c);
    EXPECT_EQ(animated.at(-10), a);
    EXPECT_EQ(animated.at(3.5f), c);
    EXPECT_EQ(animated.at(std::numeric_limits<float>::quiet_NaN()), a);
    EXPECT_EQ(animated.start_time(), 0);
    EXPECT_EQ(animated.end_time(), 3);
    EXPECT_FALSE(animated.is_static());
}

TEST(AnimatedTransform, TranslationIsLinearInTime) {
    const AnimatedTransform animated(
        {{0, Transform::translate({0, 0, 0})}, {1, Transform::translate({2, 0, 0})}});
    expect_near(animated.at(0.5f)(Point3{0, 0, 0}), {1, 0, 0}, 1e-6f);
    expect_near(animated.at(0.25f)(Point3{1, 1, 1}), {1.5f, 1, 1}, 1e-6f);
}

TEST(AnimatedTransform, RotationTurnsAtConstantSpeed) {
    const AnimatedTransform animated(
        {{0, Transform::rotate({0, 0, 1}, 0)}, {1, Transform::rotate({0, 0, 1}, 90)}});
    const float c = std::cos(kPi / 4), s = std::sin(kPi / 4);
    expect_near(animated.at(0.5f)(Point3{1, 0, 0}), {c, s, 0}, 1e-6f);
    const float third = radians(30);
    expect_near(animated.at(1 / 3.0f)(Point3{1, 0, 0}), {std::cos(third), std::sin(third), 0},
                1e-6f);
}

TEST(AnimatedTransform, RotationAndScaleInterpolateApart) {
    // Turning 0 -> 90 degrees while growing 1 -> 3 in x: halfway, 45 degrees and 2 in x.
    // Interpolating the matrices entry by entry would shrink the object on the way instead.
    const AnimatedTransform animated(
        {{0, Transform()}, {2, Transform::rotate({0, 0, 1}, 90) * Transform::scale(3, 1, 1)}});
    const Transform expected = Transform::rotate({0, 0, 1}, 45) * Transform::scale(2, 1, 1);
    expect_near(animated.at(1).matrix(), expected.matrix(), 1e-6f);
}

TEST(AnimatedTransform, MirroredKeyframesStayMirroredAndTurn) {
    const Transform mirror = Transform::scale(-1, 1, 1);
    const AnimatedTransform animated({{0, mirror}, {1, Transform::rotate({0, 0, 1}, 90) * mirror}});
    expect_near(animated.at(0.5f).matrix(), (Transform::rotate({0, 0, 1}, 45) * mirror).matrix(),
                1e-6f);
}

TEST(AnimatedTransform, InterpolatedTransformsCarryTheirInverse) {
    const AnimatedTransform animated(
        {{0, Transform::translate({1, 2, 3}) * Transform::scale(0.1f, 1, 10)},
         {1, Transform::rotate({1, 1, 0}, 170) * shear(0.7f) * Transform::scale(2, 2, 2)}});
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(-1, 1);
    for (int i = 0; i < 100; ++i) {
        const Transform t = animated.at(0.5f + 0.5f * u(rng));
        const Point3 p{u(rng), u(rng), u(rng)};
        expect_near(t.inverse()(t(p)), p, 1e-5f);
    }
}

TEST(AnimatedTransform, IsStaticWhenNothingMoves) {
    const Transform t = Transform::rotate({1, 0, 0}, 20);
    EXPECT_TRUE(AnimatedTransform().is_static());
    EXPECT_EQ(AnimatedTransform().at(5), Transform());
    EXPECT_TRUE(AnimatedTransform(t).is_static());
    EXPECT_TRUE(AnimatedTransform({{0, t}, {1, t}, {2, t}}).is_static());
    EXPECT_EQ(AnimatedTransform({{0, t}, {1, t}}).at(0.3f), t);
    EXPECT_FALSE(AnimatedTransform({{0, t}, {1, t}, {2, Transform()}}).is_static());
    // A pause between motions returns the paused keyframe itself.
    EXPECT_EQ(AnimatedTransform({{0, t}, {1, t}, {2, Transform()}}).at(0.5f), t);
}

TEST(AnimatedTransform, DescribesInvalidKeyframes) {
    using Keyframes = std::vector<Keyframe>;
    const Transform t = Transform::translate({1, 0, 0});
    EXPECT_EQ(AnimatedTransform::describe_problem({{0, t}}), "");
    EXPECT_EQ(AnimatedTransform::describe_problem({{0, t}, {1, Transform::scale(-1, 2, 1)}}),
              "keyframe 1 of 2 (time 0) and keyframe 2 of 2 (time 1) differ in handedness (one "
              "mirrors, the other does not): the motion between them would flatten the object "
              "through a singular transform");
    EXPECT_EQ(AnimatedTransform::describe_problem({}),
              "a moving transform needs at least one keyframe");
    EXPECT_EQ(AnimatedTransform::describe_problem(Keyframes{{0, t}, {0.5f, t}, {0.5f, t}}),
              "keyframe 3 of 3 (time 0.5) is not later than keyframe 2 of 3 (time 0.5): keyframe "
              "times must increase strictly");
    EXPECT_NE(AnimatedTransform::describe_problem({{1, t}, {0, t}}), "");
    EXPECT_EQ(
        AnimatedTransform::describe_problem({{std::numeric_limits<float>::quiet_NaN(), t}, {1, t}}),
        "keyframe 1 of 2 has time nan: times must be finite");
    Matrix4 flat = Matrix4::identity();
    flat.m[2][2] = 0;
    EXPECT_EQ(AnimatedTransform::describe_problem({{0, t}, {1, Transform(flat, flat)}}),
              "keyframe 2 of 2 (time 1) has a singular matrix: it flattens space");
    Matrix4 projective = Matrix4::identity();
    projective.m[3][2] = 1;
    const Transform perspective = *Transform::from_matrix(projective);
    EXPECT_NE(AnimatedTransform::describe_problem({{0, t}, {1, perspective}}).find("projective"),
              std::string::npos);
    // One keyframe is never interpolated, so any Transform will do.
    EXPECT_EQ(AnimatedTransform::describe_problem({{0, perspective}}), "");
    EXPECT_THROW(AnimatedTransform(Keyframes{}), std::invalid_argument);
    EXPECT_THROW(AnimatedTransform({{1, t}, {1, t}}), std::invalid_argument);
}

// Random keyframes: translations, non-uniform scales (all mirrored or none), some shear, and
// orientations that turn by up to 180 degrees from one keyframe to the next.
std::vector<Keyframe> random_keyframes(std::mt19937& rng) {
    std::uniform_real_distribution<float> u(-1, 1);
    std::uniform_int_distribution<int> count(2, 4);
    const float mirror = u(rng) < 0 ? -1.0f : 1.0f;
    std::vector<Keyframe> keyframes;
    float time = u(rng);
    Transform orientation = Transform::rotate({u(rng), u(rng), u(rng) + 0.01f}, 180 * u(rng));
    for (int n = count(rng), i = 0; i < n; ++i) {
        const Transform stretch =
            shear(0.5f * u(rng)) *
            Transform::scale(mirror * (1.1f + u(rng)), 1.1f + u(rng), 1.1f + u(rng));
        keyframes.push_back({time, Transform::translate({4 * u(rng), 4 * u(rng), 4 * u(rng)}) *
                                       orientation * stretch});
        time += 0.6f + 0.5f * u(rng);
        orientation =
            Transform::rotate({u(rng), u(rng), u(rng) + 0.01f}, 90 + 90 * u(rng)) * orientation;
    }
    return keyframes;
}

TEST(MotionBounds, ContainTheMovingBoxAtAllTimes) {
    std::mt19937 rng(17);
    std::uniform_real_distribution<float> u(-1, 1), unit(0, 1);
    for (int set = 0; set < 60; ++set) {
        const AnimatedTransform animated(random_keyframes(rng));
        const Point3 a{2 * u(rng), 2 * u(rng), 2 * u(rng)}, b{2 * u(rng), 2 * u(rng), 2 * u(rng)};
        const Bounds3 object = Bounds3::of(a, b);
        const float duration = animated.end_time() - animated.start_time();
        float t0 = animated.start_time() - 0.2f + (duration + 0.4f) * unit(rng);
        float t1 = animated.start_time() - 0.2f + (duration + 0.4f) * unit(rng);
        if (set % 4 == 0) t0 = animated.start_time(), t1 = animated.end_time();
        if (t1 < t0) std::swap(t0, t1);
        const Bounds3 bounds = animated.motion_bounds(object, t0, t1);
        ASSERT_TRUE(bounds.is_finite());

        std::vector<float> times{t0, t1};
        for (const Keyframe& k : animated.keyframes())
            if (t0 <= k.time && k.time <= t1) times.push_back(k.time);
        for (int i = 0; i < 2000; ++i) times.push_back(t0 + (t1 - t0) * unit(rng));
        Bounds3 seen;  // the union of the boxes actually visited: a lower bound for the answer
        for (const float t : times) {
            const Transform at = animated.at(t);
            for (int c = 0; c < 8; ++c) {
                const Point3 p = at(corner(object, c));
                ASSERT_TRUE(bounds.contains(p)) << "set " << set << " t " << t << " corner " << c;
                seen = merge(seen, p);
            }
            for (int i = 0; i < 4; ++i) {
                const Point3 p{a.x + (b.x - a.x) * unit(rng), a.y + (b.y - a.y) * unit(rng),
                               a.z + (b.z - a.z) * unit(rng)};
                ASSERT_TRUE(bounds.contains(at(p))) << "set " << set << " t " << t;
            }
        }
        // Not loose: within a few percent of what 2000 samples see.
        const Vector3 extent = bounds.diagonal(), seen_extent = seen.diagonal();
        for (int axis = 0; axis < 3; ++axis)
            EXPECT_LE(extent[axis], 1.02f * seen_extent[axis] + 1e-3f) << "set " << set;
    }
}

TEST(MotionBounds, PureTranslationGivesTheUnionOfTheEndBoxes) {
    const Bounds3 object = Bounds3::of({0, 0, 0}, {1, 1, 1});
    const AnimatedTransform animated(
        {{0, Transform::translate({0, 0, 0})}, {1, Transform::translate({2, -1, 3})}});
    const Bounds3 bounds = animated.motion_bounds(object, 0, 1);
    const Bounds3 exact = Bounds3::of({0, -1, 0}, {3, 1, 4});
    EXPECT_TRUE(contains(bounds, exact));
    expect_near(bounds.min, exact.min, 1e-4f);
    expect_near(bounds.max, exact.max, 1e-4f);
    // Half the shutter, half the sweep.
    const Bounds3 half = animated.motion_bounds(object, 0, 0.5f);
    expect_near(half.max, {2, 1, 2.5f}, 1e-4f);
}

TEST(MotionBounds, QuarterTurnOfACubeAboutItsCentreIsNearlyExact) {
    // A unit cube centred on the axis, turning 90 degrees about z: its width across x peaks at
    // 45 degrees, where the corners reach sqrt(2) / 2 from the axis.
    const Bounds3 object = Bounds3::of({-0.5f, -0.5f, -0.5f}, {0.5f, 0.5f, 0.5f});
    const AnimatedTransform animated({{0, Transform()}, {1, Transform::rotate({0, 0, 1}, 90)}});
    const Bounds3 bounds = animated.motion_bounds(object, 0, 1);
    const float exact = std::sqrt(2.0f);
    const Vector3 extent = bounds.diagonal();
    EXPECT_GE(extent.x, exact);
    EXPECT_LT(extent.x, 1.5f * exact);
    EXPECT_LT(extent.x, 1.01f * exact);
    EXPECT_LT(extent.y, 1.01f * exact);
    EXPECT_LT(extent.z, 1.01f);
}

TEST(MotionBounds, TurnAboutAnOffsetCentreMatchesDenseSampling) {
    // Turning about the box's own centre c = (2.5, 0.5, 0.5): the keyframes are
    // translate(c) rotate translate(-c), whose translation the interpolation blends linearly.
    const Bounds3 object = Bounds3::of({2, 0, 0}, {3, 1, 1});
    const Vector3 c{2.5f, 0.5f, 0.5f};
    const AnimatedTransform animated(
        {{0, Transform()},
         {1,
          Transform::translate(c) * Transform::rotate({0, 0, 1}, 90) * Transform::translate(-c)}});
    const Bounds3 bounds = animated.motion_bounds(object, 0, 1);
    Bounds3 dense;
    for (int i = 0; i <= 10000; ++i) dense = merge(dense, animated.at(i / 10000.0f)(object));
    EXPECT_TRUE(contains(bounds, dense));
    const Vector3 extent = bounds.diagonal(), dense_extent = dense.diagonal();
    for (int axis = 0; axis < 3; ++axis) {
        EXPECT_LT(extent[axis], 1.5f * dense_extent[axis]);
        EXPECT_LT(extent[axis], 1.01f * dense_extent[axis]);
    }
}

TEST(MotionBounds, StaticEmptyAndUnboundedBoxes) {
    const Transform t = Transform::rotate({0, 0, 1}, 30) * Transform::scale(2, 1, 1);
    const Bounds3 object = Bounds3::of({-1, -1, -1}, {1, 1, 1});
    expect_same(AnimatedTransform(t).motion_bounds(object, 0, 1), t(object));
    expect_same(AnimatedTransform({{0, t}, {1, t}}).motion_bounds(object, -1, 2), t(object));

    const AnimatedTransform moving(
        {{0, Transform()}, {1, Transform::translate({5, 0, 0})}, {2, t}});
    EXPECT_TRUE(moving.motion_bounds(Bounds3{}, 0, 1).is_empty());
    const Bounds3 plane{{-kInfinity, -kInfinity, 0}, {kInfinity, kInfinity, 0}};
    const Bounds3 everything = moving.motion_bounds(plane, 0, 1);
    EXPECT_EQ(everything.min, (Point3{-kInfinity, -kInfinity, -kInfinity}));
    EXPECT_EQ(everything.max, (Point3{kInfinity, kInfinity, kInfinity}));
    // Before the first keyframe the object rests there; reversed bounds are swapped.
    expect_same(moving.motion_bounds(object, -3, -1), object);
    expect_same(moving.motion_bounds(object, 1, 0), moving.motion_bounds(object, 0, 1));
    // A NaN bound stands for all times.
    const float nan = std::numeric_limits<float>::quiet_NaN();
    expect_same(moving.motion_bounds(object, nan, 1), moving.motion_bounds(object, 0, 2));
}

}  // namespace
}  // namespace glint::animated_transform_test
