#include "glint/geometry/julia_set.h"

#include <gtest/gtest.h>

#include <cmath>

#include "glint/geometry/sphere.h"
#include "glint/geometry/sphere_tracing.h"
#include "shape_property_checks.h"

namespace glint {
namespace {

using testing::expect_shape_properties;
using testing::PropertyOptions;
using testing::RandomRays;

// With c = 0 the iteration is z <- z^2: |z| stays bounded exactly when |z| <= 1, so the set is
// the unit ball and the slice w = 0 the unit sphere. After n steps |z_n| = r^(2^n) and
// |z_n'| = 2^n r^(2^n - 1), so the estimate is 0.5 r log r whatever n: at r = 2 it is
// log 2 = 0.6931 (the orbit 2, 4, 16 leaves the bailout 4 after two steps).
TEST(JuliaSet, ZeroConstantGivesTheUnitSphere) {
    const JuliaSet julia;
    EXPECT_NEAR(julia.distance_estimate({2, 0, 0}), std::log(2.0), 1e-12);
    EXPECT_NEAR(julia.distance_estimate({0, 0.6f, 0.8f}), 0, 1e-6);  // on the sphere
    EXPECT_LT(julia.distance_estimate({0, 0.5f, 0}), 0);             // inside
    EXPECT_DOUBLE_EQ(julia.escape_radius(), 1);
    EXPECT_NEAR(julia.bounding_radius(), 1.01 + 2e-3, 1e-9);
}

// Sphere tracing stops once 0.5 r log r < epsilon, i.e. at 1 <= r < 1 + 2 epsilon (log r
// ~ r - 1): every hit lies that close outside the sphere, along the analytic sphere's ray.
TEST(JuliaSet, HitsLieWithinTwoEpsilonsOutsideTheUnitSphere) {
    const JuliaSet julia;
    const Sphere unit{{0, 0, 0}, 1};
    RandomRays rays({0, 0, 0}, 1.2f, 17);
    int hits = 0;
    for (int i = 0; i < 1000; ++i) {
        const Ray ray = rays.next();
        const auto hit = julia.intersect(ray, {});
        // Rays passing clearly through the sphere must hit; grazing ones may go either way.
        const Vector3 o = to_vector(ray.origin);
        const float closest = length(o - ray.direction * dot(o, ray.direction));
        if (unit.intersect(ray, {}) && closest < 0.99f) {
            ASSERT_TRUE(hit) << "ray " << i;
        }
        if (!hit) continue;
        ++hits;
        const float r = length(to_vector(ray.at(hit->t)));
        EXPECT_GE(r, 1 - 1e-5f) << "ray " << i;
        EXPECT_LE(r, 1 + 2 * julia.epsilon) << "ray " << i;
        EXPECT_LT(julia.distance_estimate(ray.at(hit->t)), julia.epsilon);
    }
    EXPECT_GT(hits, 300);
}

TEST(JuliaSet, TighterEpsilonHitsCloserToTheSurface) {
    JuliaSet julia;
    const Ray ray{{0.1f, 0.2f, -3}, {0, 0, 1}};
    float previous_gap = 1;
    for (const float epsilon : {1e-2f, 1e-3f, 1e-4f, 1e-5f}) {
        julia.epsilon = epsilon;
        const auto hit = julia.intersect(ray, {});
        ASSERT_TRUE(hit);
        const float gap = length(to_vector(ray.at(hit->t))) - 1;
        EXPECT_GE(gap, -1e-6f);
        EXPECT_LE(gap, 2 * epsilon);
        EXPECT_LT(gap, previous_gap);
        previous_gap = gap;
    }
}

TEST(JuliaSet, NormalsAreUnitAndRadialForTheSphere) {
    const JuliaSet julia;
    RandomRays rays({0, 0, 0}, 1, 23);
    for (int i = 0; i < 200; ++i) {
        const Ray ray = rays.next();
        const auto hit = julia.intersect(ray, {});
        if (!hit) continue;
        const SurfacePoint sp = julia.surface_at(ray, *hit);
        EXPECT_NEAR(length(to_vector(sp.normal)), 1, 1e-5);
        EXPECT_EQ(sp.normal, sp.shading_normal);
        EXPECT_GT(dot(sp.normal, normalize(to_vector(sp.p))), 0.999f);
    }
}

// The 4D unit ball cut at w = 0.6 is the sphere of radius sqrt(1 - 0.36) = 0.8.
TEST(JuliaSet, SliceOfTheFourDimensionalSet) {
    JuliaSet julia;
    julia.slice_w = 0.6f;
    const Ray ray{{0, 0, -3}, {0, 0, 1}};
    const auto hit = julia.intersect(ray, {});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 3 - 0.8, 3 * julia.epsilon);
    julia.slice_w = 1.5f;  // beyond the set's ball: nothing to hit
    EXPECT_EQ(julia.bounding_radius(), 0);
    EXPECT_FALSE(julia.intersect(ray, {}));
}

TEST(JuliaSet, EscapeRadiusBoundsTheSet) {
    JuliaSet julia;
    julia.c = {0.75f, 0, 0, 0};  // R = (1 + sqrt(1 + 3)) / 2 = 1.5
    EXPECT_DOUBLE_EQ(julia.escape_radius(), 1.5);
    julia.c = {-0.2f, 0.6f, 0.2f, 0};
    const double r = julia.escape_radius();
    RandomRays rays({0, 0, 0}, 1.5f, 3);
    for (int i = 0; i < 200; ++i) {
        const Ray ray = rays.next();
        if (const auto hit = julia.intersect(ray, {})) {
            EXPECT_LE(length(to_vector(ray.at(hit->t))), r + 2 * julia.epsilon);
        }
    }
}

TEST(JuliaSet, RaysMissingTheBoundingSphereMiss) {
    JuliaSet julia;
    julia.c = {-0.2f, 0.6f, 0.2f, 0};
    EXPECT_FALSE(julia.intersect({{2, 2, -3}, {0, 0, 1}}, {}));
    EXPECT_FALSE(julia.intersect({{0, 0, -3}, {0, 0, -1}}, {}));     // pointing away
    EXPECT_FALSE(julia.intersect({{0, 0, -3}, {0, 0, 1}}, {0, 1}));  // stops short
}

TEST(JuliaSet, RaysFromInsideTheBoundingSphere) {
    const JuliaSet julia;
    // From outside the set: the same surface point as from afar.
    const Ray near{{0, 0, -1.005f}, {0, 0, 1}};
    const auto hit = julia.intersect(near, {});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(near.at(hit->t).z, -1, 2 * julia.epsilon);
    // From inside the set: where the ray leaves the ball, x^2 + 0.3^2 = 1, up to the 2 epsilon
    // shell, marked as leaving, with the normal pointing out along the radius.
    const Ray inside{{0, 0, 0.3f}, {1, 0, 0}};
    const auto exit = julia.intersect(inside, {0.01f, kInfinity});
    ASSERT_TRUE(exit);
    EXPECT_GE(exit->t, std::sqrt(1 - 0.09f) - 1e-5f);
    EXPECT_LE(exit->t, std::sqrt(std::pow(1 + 2 * julia.epsilon, 2.0f) - 0.09f) + 2e-5f);
    EXPECT_EQ(exit->part, kLeavingHit);
    EXPECT_FALSE(julia.inside(inside.at(exit->t)));
    EXPECT_TRUE(julia.inside(inside.at(exit->t - 1e-4f)));
    const SurfacePoint sp = julia.surface_at(inside, *exit);
    EXPECT_GT(dot(sp.normal, normalize(to_vector(sp.p))), 0.999f);
    // A range that ends inside the set holds no crossing.
    EXPECT_FALSE(julia.intersect(inside, {0, 0.5f}));
}

TEST(JuliaSet, RayLeavingTheSurfaceDoesNotHitItAgain) {
    const JuliaSet julia;
    const Ray ray{{0.2f, 0.1f, -3}, {0, 0, 1}};
    const auto hit = julia.intersect(ray, {});
    ASSERT_TRUE(hit);
    const SurfacePoint sp = julia.surface_at(ray, *hit);
    // A shadow ray from the hit point itself, inside the epsilon shell, towards a light.
    const Vector3 to_light = normalize(to_vector(sp.normal) + Vector3{0.5f, 0.3f, 0});
    EXPECT_FALSE(julia.intersect({sp.p, to_light}, {}));
    // Into the surface instead: it crosses the ball and leaves it on the far side, at the
    // mirror image of the hit point (z -> -z), up to the epsilon shells.
    const auto leaving = julia.intersect({sp.p, ray.direction}, {});
    ASSERT_TRUE(leaving);
    EXPECT_EQ(leaving->part, kLeavingHit);
    EXPECT_NEAR(sp.p.z + leaving->t, -sp.p.z, 4 * julia.epsilon);
}

TEST(JuliaSet, EstimateIsNeverNaN) {
    JuliaSet julia;
    julia.c = {-0.2f, 0.6f, 0.2f, 0};
    EXPECT_TRUE(std::isfinite(julia.distance_estimate({0, 0, 0})));
    julia.c = {0, 0, 0, 0};
    EXPECT_TRUE(std::isfinite(julia.distance_estimate({0, 0, 0})));  // z = 0: 0 * log 0
    julia.max_iterations = 1000;
    julia.bailout = 1e6f;
    EXPECT_TRUE(std::isfinite(julia.distance_estimate({1.5f, 0, 0})));
}

// The hit converges as the iteration count grows: beyond 12 iterations it no longer moves by
// more than epsilon.
TEST(JuliaSet, MoreIterationsConverge) {
    JuliaSet julia;
    julia.c = {-0.2f, 0.6f, 0.2f, 0};
    const Ray ray{{0, 0, -3}, {0, 0, 1}};
    julia.max_iterations = 40;
    const float reference = julia.intersect(ray, {})->t;
    for (const int n : {12, 16, 24}) {
        julia.max_iterations = n;
        EXPECT_NEAR(julia.intersect(ray, {})->t, reference, julia.epsilon) << n;
    }
}

TEST(JuliaSet, StepCapEndsTheTrace) {
    JuliaSet julia;
    julia.max_steps = 2;
    const Ray ray{{0.1f, 0.2f, -3}, {0, 0, 1}};
    EXPECT_FALSE(julia.intersect(ray, {}));
    const auto estimate = [&](Point3 p) { return julia.distance_estimate(p); };
    const SphereTrace trace = sphere_trace(
        estimate, ray, {}, {{}, julia.bounding_radius(), julia.epsilon, julia.max_steps});
    EXPECT_EQ(trace.outcome, SphereTrace::Outcome::kStepCap);
    EXPECT_EQ(trace.steps, 2);
}

TEST(JuliaSet, ScaleAndCenterPlaceTheSet) {
    JuliaSet julia;
    julia.center = {1, 2, 3};
    julia.scale = 2;
    const Ray ray{{1, 2, -3}, {0, 0, 1}};
    const auto hit = julia.intersect(ray, {});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 6 - 2, 2 * julia.epsilon);  // a sphere of radius 2 about z = 3
    EXPECT_EQ(julia.bounds().min.x, 1 - float(julia.bounding_radius()));
}

// Bounds: the cube around the bounding sphere of the slice, and no point of the solid outside
// it (brute force over a grid of twice its size); a slice beyond the set has nothing to bound.
TEST(JuliaSet, BoundsHoldTheSolid) {
    JuliaSet julia;
    julia.c = {-0.2f, 0.6f, 0.2f, 0};
    julia.slice_w = 0.1f;
    julia.center = {0.5f, -1, 2};
    julia.scale = 0.8f;
    const float r = float(julia.bounding_radius());
    // The slice of the ball of radius R = (1 + sqrt(1 + 4|c|)) / 2, scaled, plus the margins.
    const double big_r = julia.escape_radius();
    EXPECT_NEAR(r, 0.8 * std::sqrt(big_r * big_r - 0.01) * 1.01 + 2 * julia.epsilon, 1e-5);
    const Bounds3 b = julia.bounds();
    EXPECT_EQ(b.min, (julia.center - Vector3{r, r, r}));
    EXPECT_EQ(b.max, (julia.center + Vector3{r, r, r}));
    constexpr int kN = 48;
    int inside = 0;
    for (int i = 0; i <= kN; ++i) {
        for (int j = 0; j <= kN; ++j) {
            for (int k = 0; k <= kN; ++k) {
                const Vector3 offset =
                    Vector3{float(i), float(j), float(k)} / float(kN) * 2.0f - Vector3{1, 1, 1};
                const Point3 p = julia.center + offset * (2 * r);
                if (!julia.inside(p)) continue;
                ++inside;
                ASSERT_TRUE(b.contains(p)) << p.x << ", " << p.y << ", " << p.z;
            }
        }
    }
    EXPECT_GT(inside, 100);
    julia.slice_w = 5;  // beyond R: an empty slice
    EXPECT_EQ(julia.bounds().min, julia.center);
    EXPECT_EQ(julia.bounds().max, julia.center);
}

// uv is the spherical mapping about the centre, as for Sphere: on the c = 0 set (a sphere) the
// hit from each axis direction has that direction's longitude and latitude.
TEST(JuliaSet, UvsAreSphericalAboutTheCentre) {
    JuliaSet julia;
    julia.center = {1, 2, 3};
    julia.scale = 2;
    const Sphere same{julia.center, 2};
    RandomRays rays(julia.center, 2.5f, 41);
    int hits = 0;
    for (int i = 0; i < 200; ++i) {
        const Ray ray = rays.next();
        const auto a = julia.intersect(ray, {});
        const auto b = same.intersect(ray, {});
        if (!a || !b) continue;
        // Grazing rays meet the shell (2e-3 deep at this scale) far from where they meet the
        // sphere.
        if (dot(same.surface_at(ray, *b).normal, ray.direction) > -0.3f) continue;
        ++hits;
        const Point2 ua = julia.surface_at(ray, *a).uv, ub = same.surface_at(ray, *b).uv;
        // Away from the seam at u = 0, the two agree to about the shell's depth.
        if (ub.x > 0.01f && ub.x < 0.99f) {
            EXPECT_NEAR(ua.x, ub.x, 4e-3f) << "ray " << i;
        }
        EXPECT_NEAR(ua.y, ub.y, 4e-3f) << "ray " << i;
    }
    EXPECT_GT(hits, 50);
    // From -z: a quarter turn from +x, on the equator.
    const Ray from_front{{1, 2, -3}, {0, 0, 1}};
    const Point2 uv = julia.surface_at(from_front, *julia.intersect(from_front, {})).uv;
    EXPECT_NEAR(uv.x, 0.25f, 1e-5f);
    EXPECT_NEAR(uv.y, 0.5f, 1e-5f);
}

TEST(JuliaSet, ParameterChecks) {
    JuliaSet julia;
    EXPECT_EQ(describe_problem(julia), "");
    julia.epsilon = 0;
    EXPECT_EQ(describe_problem(julia), "julia epsilon must be > 0, got 0");
    julia.epsilon = 1e-3f;
    julia.c = {3, 0, 0, 0};  // R = (1 + sqrt 13) / 2 = 2.30 > 2
    julia.bailout = 2;
    EXPECT_EQ(describe_problem(julia),
              "julia bailout must be between the escape radius 2.30278 and 1e6, got 2");
    julia.bailout = 4;
    julia.max_iterations = 0;
    EXPECT_EQ(describe_problem(julia), "julia max_iterations must be in [1, 1000], got 0");
    julia.max_iterations = 10;
    julia.scale = -1;
    EXPECT_EQ(describe_problem(julia), "julia scale must be > 0, got -1");
    julia.scale = 1;
    julia.c[2] = std::nanf("");
    EXPECT_EQ(describe_problem(julia), "julia c must be finite");
}

TEST(JuliaSet, ShapePropertiesOfTheSphere) {
    const JuliaSet julia;
    PropertyOptions options;
    options.convex = true;
    options.rays = 1000;
    options.surface_tolerance = 2 * julia.epsilon;
    options.normal_matches_gradient = true;  // the estimated normals are radial
    expect_shape_properties(
        julia, [](Point3 p) { return length(to_vector(p)) - 1 - 0.001f; }, RandomRays({0, 0, 0}, 1),
        options);
}

TEST(JuliaSet, ShapePropertiesOfAConnectedJuliaSet) {
    JuliaSet julia;
    julia.c = {-0.2f, 0.6f, 0.2f, 0};
    PropertyOptions options;
    options.rays = 500;
    options.min_hits = 100;
    options.surface_tolerance = julia.epsilon;
    // Secondary rays from a fractal start beyond its epsilon shell (docs/implicit-surfaces.md);
    // from inside it, rough spots at the epsilon scale may count as entering.
    options.leave_offset = 2 * julia.epsilon;
    options.min_rehit_distance = 0.5f * julia.epsilon;
    // The normal is the estimate's gradient by differences of step epsilon / 2; the check's
    // stencil is twice as wide, and the estimate (rounded to float here) is smooth enough there
    // for 11 degrees (the worst of these hits is at 9).
    options.normal_matches_gradient = true;
    options.gradient_step = julia.epsilon;
    options.gradient_min_cos = 0.98f;
    expect_shape_properties(
        julia, [&](Point3 p) { return float(julia.distance_estimate(p)) - 0.5f * julia.epsilon; },
        RandomRays({0, 0, 0}, 1.2f), options);
}

}  // namespace
}  // namespace glint
