#include "glint/geometry/quadric.h"

#include <gtest/gtest.h>

#include <cmath>

#include "glint/geometry/sphere.h"
#include "shape_property_checks.h"

namespace glint::quadric_test {
namespace {

using testing::expect_shape_properties;
using testing::PropertyOptions;
using testing::RandomRays;

//                          A  B  C  D  E  F  G  H  I  J
const Quadric kUnitSphere{{1, 1, 1, 0, 0, 0, 0, 0, 0, -1}, {{-2, -2, -2}, {2, 2, 2}}};

void expect_normal(Normal3 n, Vector3 expected) {
    const Vector3 e = normalize(expected);
    EXPECT_NEAR(n.x, e.x, 1e-6f);
    EXPECT_NEAR(n.y, e.y, 1e-6f);
    EXPECT_NEAR(n.z, e.z, 1e-6f);
}

// f / |grad f|: the distance to the surface to first order, what the property checks need.
float first_order_distance(const Quadric& q, Point3 p) {
    const auto g = quadric_gradient(q, p.x, p.y, p.z);
    return static_cast<float>(quadric_value(q, p.x, p.y, p.z) /
                              std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]));
}

TEST(Quadric, SphereWorkedHit) {
    // x^2 + y^2 + z^2 - 1 = 0 from (0 0 -5) along +z: t = 4, normal (0 0 -1).
    const Ray ray{{0, 0, -5}, {0, 0, 1}};
    const auto hit = kUnitSphere.intersect(ray, {});
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit->t, 4);
    const SurfacePoint sp = kUnitSphere.surface_at(ray, *hit);
    EXPECT_NEAR(distance(sp.p, {0, 0, -1}), 0, 1e-6f);
    expect_normal(sp.normal, {0, 0, -1});
    EXPECT_EQ(sp.shading_normal, sp.normal);
    // uv: x and z across the clip box [-2, 2]: (0 - -2) / 4 and (-1 - -2) / 4.
    EXPECT_NEAR(sp.uv.x, 0.5f, 1e-6f);
    EXPECT_NEAR(sp.uv.y, 0.25f, 1e-6f);
    const auto far = kUnitSphere.intersect(ray, {4.5f, kInfinity});
    ASSERT_TRUE(far);
    EXPECT_FLOAT_EQ(far->t, 6);
}

TEST(Quadric, SphereAgreesWithTheSphereShape) {
    const Sphere sphere{{0, 0, 0}, 1};
    RandomRays rays({0, 0, 0}, 1.2f, 5);
    for (int i = 0; i < 500; ++i) {
        const Ray ray = rays.next();
        const auto a = sphere.intersect(ray, {});
        const auto b = kUnitSphere.intersect(ray, {});
        ASSERT_EQ(bool(a), bool(b)) << i;
        if (!a) continue;
        EXPECT_NEAR(a->t, b->t, 1e-5f) << i;
        const Normal3 na = sphere.surface_at(ray, *a).normal;
        const Normal3 nb = kUnitSphere.surface_at(ray, *b).normal;
        EXPECT_NEAR(dot(na, nb), 1, 1e-6f) << i;
    }
}

TEST(Quadric, HyperboloidOfOneSheet) {
    // x^2 - y^2 + z^2 - 1 = 0 between y = -1 and 1. Along x at y = 1: x^2 = 2, so the ray hits
    // x = -sqrt 2 with normal (2x, -2y, 0) = (-2 sqrt 2, -2, 0) / |.|.
    const Quadric hyperboloid{{1, -1, 1, 0, 0, 0, 0, 0, 0, -1}, {{-3, -1, -3}, {3, 1, 3}}};
    const Ray ray{{-5, 1, 0}, {1, 0, 0}};
    const auto hit = hyperboloid.intersect(ray, {});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 5 - std::sqrt(2.0f), 1e-6f);
    expect_normal(hyperboloid.surface_at(ray, *hit).normal, {-std::sqrt(2.0f), -1, 0});
    // Up the middle there is nothing: -y^2 - 1 never vanishes.
    EXPECT_FALSE(hyperboloid.intersect({{0, -5, 0}, {0, 1, 0}}, {}));
    // The waist: radius 1 at y = 0.
    const auto waist = hyperboloid.intersect({{0, 0, -5}, {0, 0, 1}}, {});
    ASSERT_TRUE(waist);
    EXPECT_FLOAT_EQ(waist->t, 4);
}

TEST(Quadric, ClippedParaboloid) {
    // y = x^2 + z^2, i.e. x^2 + z^2 - y = 0, kept below y = 1.
    const Quadric bowl{{1, 0, 1, 0, 0, 0, 0, -1, 0, 0}, {{-2, -1, -2}, {2, 1, 2}}};
    // Down at x = 0.5: y = 0.25, t = 4.75; normal (2x, -1, 0) = (1, -1, 0) / sqrt 2 (the side
    // where f > 0, outside the bowl).
    const Ray ray{{0.5f, 5, 0}, {0, -1, 0}};
    const auto hit = bowl.intersect(ray, {});
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit->t, 4.75f);
    expect_normal(bowl.surface_at(ray, *hit).normal, {1, -1, 0});
    // Across at y = 0.5 the bowl has radius sqrt 0.5; at y = 2 it is clipped away.
    const auto across = bowl.intersect({{-5, 0.5f, 0}, {1, 0, 0}}, {});
    ASSERT_TRUE(across);
    EXPECT_NEAR(across->t, 5 - std::sqrt(0.5f), 1e-6f);
    EXPECT_FALSE(bowl.intersect({{-5, 2, 0}, {1, 0, 0}}, {}));
    // Down at x = 1.5 the surface is at y = 2.25, above the clip box: the ray passes.
    EXPECT_FALSE(bowl.intersect({{1.5f, 5, 0}, {0, -1, 0}}, {}));
}

TEST(Quadric, PlaneWithoutSecondOrderTerms) {
    // y - 0.5 = 0 in the box [-1, 1]^3.
    const Quadric plane{{0, 0, 0, 0, 0, 0, 0, 1, 0, -0.5f}, {{-1, -1, -1}, {1, 1, 1}}};
    const Ray down{{0.2f, 5, 0.3f}, {0, -1, 0}};
    const auto hit = plane.intersect(down, {});
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit->t, 4.5f);
    expect_normal(plane.surface_at(down, *hit).normal, {0, 1, 0});
    const Ray oblique{{0, 1.5f, 0}, normalize(Vector3{1, -1, 0})};
    const auto o = plane.intersect(oblique, {});
    ASSERT_TRUE(o);
    EXPECT_NEAR(o->t, std::sqrt(2.0f), 1e-6f);
    EXPECT_FALSE(plane.intersect({{1.5f, 5, 0}, {0, -1, 0}}, {}));   // outside the box
    EXPECT_FALSE(plane.intersect({{-5, 0.25f, 0}, {1, 0, 0}}, {}));  // parallel
}

TEST(Quadric, InfiniteCylinderClippedToABox) {
    // x^2 + z^2 - 1 = 0 along y, kept for 0 <= y <= 1: the unit cylinder of the Cylinder tests.
    const Quadric tube{{1, 0, 1, 0, 0, 0, 0, 0, 0, -1}, {{-1, 0, -1}, {1, 1, 1}}};
    const Ray ray{{-5, 0.5f, 0}, {1, 0, 0}};
    const auto hit = tube.intersect(ray, {});
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit->t, 4);
    expect_normal(tube.surface_at(ray, *hit).normal, {-1, 0, 0});
    EXPECT_FALSE(tube.intersect({{-5, 1.5f, 0}, {1, 0, 0}}, {}));  // above the box
    EXPECT_FALSE(tube.intersect({{0.5f, -5, 0}, {0, 1, 0}}, {}));  // along the axis, inside
}

TEST(Quadric, ConeApexHasAFallbackNormal) {
    // x^2 + z^2 - y^2 = 0: straight down the axis the ray only touches the apex, where the
    // gradient vanishes; the normal then faces back along the ray.
    const Quadric cone{{1, -1, 1, 0, 0, 0, 0, 0, 0, 0}, {{-1, -1, -1}, {1, 1, 1}}};
    const Ray ray{{0, 5, 0}, {0, -1, 0}};
    const auto hit = cone.intersect(ray, {});
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit->t, 5);
    const SurfacePoint sp = cone.surface_at(ray, *hit);
    EXPECT_EQ(sp.normal, (Normal3{0, 1, 0}));
}

TEST(Quadric, FarRaysStayAccurate) {
    const Ray ray{{0, 0.1f, -1e4f}, {0, 0, 1}};
    const auto hit = kUnitSphere.intersect(ray, {});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 1e4 - std::sqrt(0.99), 1e-3);
    const SurfacePoint sp = kUnitSphere.surface_at(ray, *hit);
    EXPECT_NEAR(length(to_vector(sp.p)), 1, 1e-6f);
}

// A paraboloid cut 10^5 out, as glint cuts POV-Ray's unbounded quadrics: the chord's middle lies
// 10^5 away, so the equation's terms near 10^20 must not be rounded to float (every second ray
// missed the surface then). Rays from near the surface find it where it is.
TEST(Quadric, NearHitsInAFarBoxStayAccurate) {
    //                 x^2 + z^2 - y = 0
    const Quadric paraboloid{{1, 0, 1, 0, 0, 0, 0, -1, 0, 0},
                             {{-1e5f, -1e5f, -1e5f}, {1e5f, 1e5f, 1e5f}}};
    for (int i = 0; i < 100; ++i) {
        // From (x0, 0, -3) up along y: the surface at y = x0^2 + 9.
        const float x0 = -2 + 0.04f * float(i);
        const Ray ray{{x0, 0, -3}, {0, 1, 0}};
        const auto hit = paraboloid.intersect(ray, {});
        ASSERT_TRUE(hit) << x0;
        EXPECT_NEAR(hit->t, x0 * x0 + 9, 1e-4) << x0;
    }
}

TEST(Quadric, BoundsAreTheClipBox) {
    EXPECT_EQ(kUnitSphere.bounds().min, (Point3{-2, -2, -2}));
    EXPECT_EQ(kUnitSphere.bounds().max, (Point3{2, 2, 2}));
}

TEST(Quadric, DescribesBadDescriptions) {
    EXPECT_EQ(describe_problem(kUnitSphere), "");
    EXPECT_EQ(describe_problem(Quadric{{0, 0, 0, 0, 0, 0, 0, 0, 0, 1}, kUnitSphere.clip}),
              "quadric coefficients A to I must not all be 0: the equation has no surface");
    EXPECT_EQ(describe_problem(Quadric{{1, 1, 1, 0, 0, 0, 0, 0, NAN, -1}, kUnitSphere.clip}),
              "quadric coefficient I must be finite, got nan");
    EXPECT_EQ(describe_problem(Quadric{{1, 1, 1, 0, 0, 0, 0, 0, 0, -1}}),
              "quadric clip box must be finite with min <= max on every axis");
    EXPECT_EQ(describe_problem(Quadric{{1, 1, 1, 0, 0, 0, 0, 0, 0, -1}, {{0, 0, 0}, {1, -1, 1}}}),
              "quadric clip box must be finite with min <= max on every axis");
}

TEST(Quadric, PropertyChecks) {
    PropertyOptions convex;
    convex.convex = true;
    convex.normal_matches_gradient = true;
    PropertyOptions open;
    open.normal_matches_gradient = true;
    // A rotated, shifted ellipsoid wholly inside its box: a convex closed surface.
    const Quadric ellipsoid{{1, 2, 1.5f, 0.6f, -0.4f, 0.3f, 0.2f, -0.1f, 0.3f, -1},
                            {{-3, -3, -3}, {3, 3, 3}}};
    expect_shape_properties(
        ellipsoid, [&](Point3 p) { return first_order_distance(ellipsoid, p); },
        RandomRays({0, 0, 0}, 1.5f), convex);
    // A hyperboloid of one sheet, tilted by cross terms, clipped to a box.
    const Quadric hyperboloid{{1, -0.8f, 1, 0.3f, 0, -0.2f, 0, 0, 0, -0.5f},
                              {{-1.5f, -1.5f, -1.5f}, {1.5f, 1.5f, 1.5f}}};
    expect_shape_properties(
        hyperboloid, [&](Point3 p) { return first_order_distance(hyperboloid, p); },
        RandomRays({0, 0, 0}, 1.5f, 3), open);
    // A hyperbolic paraboloid (a saddle), y = x^2 - z^2.
    const Quadric saddle{{1, 0, -1, 0, 0, 0, 0, -1, 0, 0}, {{-1, -1, -1}, {1, 1, 1}}};
    expect_shape_properties(
        saddle, [&](Point3 p) { return first_order_distance(saddle, p); },
        RandomRays({0, 0, 0}, 1.5f, 4), open);
}

TEST(Quadric, InsideExtentCompletesTheSquares) {
    // x^2/4 + y^2 + z^2 - 1 < 0: the ellipsoid of half-axes 2, 1, 1.
    Bounds3 b = inside_extent({0.25f, 1, 1, 0, 0, 0, 0, 0, 0, -1});
    EXPECT_EQ(b.min, (Point3{-2, -1, -1}));
    EXPECT_EQ(b.max, (Point3{2, 1, 1}));
    // (x - 1)^2 + y^2 - 4 = x^2 + y^2 - 2x - 3: a cylinder along z of radius 2 about x = 1.
    b = inside_extent({1, 1, 0, 0, 0, 0, -2, 0, 0, -3});
    EXPECT_EQ(b.min, (Point3{-1, -2, -kInfinity}));
    EXPECT_EQ(b.max, (Point3{3, 2, kInfinity}));
    // x^2 + y^2 + 1 < 0 has no inside.
    EXPECT_TRUE(inside_extent({1, 1, 0, 0, 0, 0, 0, 0, 0, 1}).is_empty());
    // A cone (a negative square), a paraboloid (x alone linear) and a tilted cylinder (a cross
    // term) are unbounded on every axis here.
    for (const std::array<float, 10> c : {std::array<float, 10>{1, -1, 1, 0, 0, 0, 0, 0, 0, 0},
                                          std::array<float, 10>{0, 1, 1, 0, 0, 0, -1, 0, 0, 0},
                                          std::array<float, 10>{1, 1, 0, 1, 0, 0, 0, 0, 0, -1}}) {
        b = inside_extent(c);
        EXPECT_EQ(b.min, (Point3{-kInfinity, -kInfinity, -kInfinity}));
        EXPECT_EQ(b.max, (Point3{kInfinity, kInfinity, kInfinity}));
    }
}

}  // namespace
}  // namespace glint::quadric_test
