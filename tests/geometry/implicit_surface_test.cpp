#include "glint/geometry/implicit_surface.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <vector>

#include "glint/geometry/sphere.h"
#include "shape_property_checks.h"

namespace glint {
namespace {

using testing::expect_shape_properties;
using testing::PropertyOptions;
using testing::RandomRays;

std::shared_ptr<const Expression> function(std::string_view source,
                                           const ExpressionConstants& constants = {}) {
    auto result = compile_expression(source, constants);
    if (auto* error = std::get_if<ExpressionError>(&result)) {
        ADD_FAILURE() << source << ": " << error->message;
        return nullptr;
    }
    return std::make_shared<const Expression>(std::get<Expression>(std::move(result)));
}

ImplicitSurface surface(std::string_view source, Bounds3 region,
                        const ExpressionConstants& constants = {}) {
    ImplicitSurface s;
    s.f = function(source, constants);
    s.region = region;
    return s;
}

Bounds3 cube(float half) { return {{-half, -half, -half}, {half, half, half}}; }

// ---- an exact reference for polynomial surfaces --------------------------------------------
// Polynomials in t, coefficients in ascending order, evaluated in double.
using Polynomial = std::vector<double>;

Polynomial multiply(const Polynomial& a, const Polynomial& b) {
    Polynomial r(a.size() + b.size() - 1, 0.0);
    for (std::size_t i = 0; i < a.size(); ++i)
        for (std::size_t j = 0; j < b.size(); ++j) r[i + j] += a[i] * b[j];
    return r;
}
Polynomial add(Polynomial a, const Polynomial& b, double scale = 1) {
    if (a.size() < b.size()) a.resize(b.size(), 0.0);
    for (std::size_t i = 0; i < b.size(); ++i) a[i] += scale * b[i];
    return a;
}
double evaluate(const Polynomial& p, double t) {
    double v = 0;
    for (std::size_t i = p.size(); i-- > 0;) v = v * t + p[i];
    return v;
}

// All real roots in [lo, hi] of a polynomial: between consecutive roots of its derivative it
// is monotonic, so each piece holds at most one root, found by bisection. (Double roots are
// found only where the derivative's root lands exactly on 0; the tests allow for that.)
std::vector<double> roots(const Polynomial& p, double lo, double hi) {
    if (p.size() <= 1) return {};
    Polynomial derivative;
    for (std::size_t i = 1; i < p.size(); ++i) derivative.push_back(double(i) * p[i]);
    std::vector<double> ends{lo};
    for (const double c : roots(derivative, lo, hi)) ends.push_back(c);
    ends.push_back(hi);
    std::vector<double> found;
    for (std::size_t k = 0; k + 1 < ends.size(); ++k) {
        double a = ends[k], b = ends[k + 1];
        double fa = evaluate(p, a);
        if (fa == 0) {
            found.push_back(a);
            continue;
        }
        if (fa * evaluate(p, b) > 0) continue;
        for (int i = 0; i < 200 && b - a > 1e-15; ++i) {
            const double m = 0.5 * (a + b), fm = evaluate(p, m);
            if ((fm < 0) == (fa < 0)) {
                a = m;
                fa = fm;
            } else {
                b = m;
            }
        }
        found.push_back(0.5 * (a + b));
    }
    return found;
}

// The torus of radii R (around y) and r along a ray, as a quartic in t.
Polynomial torus_along(const Ray& ray, double R, double r) {
    const double ox = ray.origin.x, oy = ray.origin.y, oz = ray.origin.z;
    const double dx = ray.direction.x, dy = ray.direction.y, dz = ray.direction.z;
    const Polynomial all{ox * ox + oy * oy + oz * oz + R * R - r * r,
                         2 * (ox * dx + oy * dy + oz * dz), dx * dx + dy * dy + dz * dz};
    const Polynomial ring{ox * ox + oz * oz, 2 * (ox * dx + oz * dz), dx * dx + dz * dz};
    return add(multiply(all, all), ring, -4 * R * R);
}

// ---- worked examples -----------------------------------------------------------------------

// The unit sphere from (0, 0, -3) along +z, region [-1.5, 1.5]^3, so t runs over [1.5, 4.5] and
// f(t) = (t - 3)^2 - 1. [1.5, 4.5]: the slope 2(t - 3) spans [-3, 3], split. [1.5, 3]: slope
// [-3, 0], still holds 0, split. [1.5, 2.25]: slope [-3, -1.5], monotonic, f(1.5) = 1.25 > 0 >
// f(2.25) = -0.4375: a sign change, refined by Newton from the midpoint 1.875 to t = 2.
TEST(ImplicitSurface, WorkedExampleUnitSphere) {
    const ImplicitSurface s = surface("x^2 + y^2 + z^2 - 1", cube(1.5f));
    const Ray ray{{0, 0, -3}, {0, 0, 1}};
    const ImplicitSearch search = find_first_root(s, ray, {});
    ASSERT_TRUE(search.hit);
    EXPECT_EQ(search.found, ImplicitSearch::Found::kSignChange);
    EXPECT_EQ(search.segments, 3);
    EXPECT_FLOAT_EQ(search.hit->t, 2);
    const SurfacePoint sp = s.surface_at(ray, *search.hit);
    EXPECT_EQ(sp.normal, (Normal3{0, 0, -1}));  // along grad f: outwards
    EXPECT_EQ(sp.shading_normal, sp.normal);
    EXPECT_NEAR(sp.uv.x, 0.25, 1e-6);  // spherical about the region's centre, as Sphere
    EXPECT_NEAR(sp.uv.y, 0.5, 1e-6);
}

TEST(ImplicitSurface, AgreesWithTheAnalyticSphereOnRandomRays) {
    const Sphere sphere{{0.2f, -0.1f, 0.3f}, 1.1f};
    const ImplicitSurface s =
        surface("(x - 0.2)^2 + (y + 0.1)^2 + (z - 0.3)^2 - 1.1^2", cube(1.6f));
    RandomRays rays({0, 0, 0}, 1.5f, 99);
    int hits = 0;
    for (int i = 0; i < 2000; ++i) {
        const Ray ray = rays.next();
        const auto expected = sphere.intersect(ray, {});
        const auto got = s.intersect(ray, {});
        if (expected) {
            ASSERT_TRUE(got) << "ray " << i << " missed; sphere hit at " << expected->t;
            EXPECT_NEAR(got->t, expected->t, s.tolerance) << "ray " << i;
            ++hits;
        } else if (got) {
            // Only a near miss may count as a (tangential) hit.
            EXPECT_NEAR(distance(ray.at(got->t), sphere.center), sphere.radius, s.tolerance);
        }
    }
    EXPECT_GT(hits, 300);
}

TEST(ImplicitSurface, AgreesWithTheAnalyticTorusOnRandomRays) {
    const double R = 1, r = 0.4;
    const ImplicitSurface s =
        surface("(x^2 + y^2 + z^2 + R^2 - r^2)^2 - 4*R^2*(x^2 + z^2)",
                {{-1.5f, -0.5f, -1.5f}, {1.5f, 0.5f, 1.5f}}, {{"R", R}, {"r", r}});
    RandomRays rays({0, 0, 0}, 1.5f, 7);
    int hits = 0, inner_hits = 0;
    for (int i = 0; i < 2000; ++i) {
        const Ray ray = rays.next();
        const auto clipped = intersect_slabs(s.region, ray, {});
        std::vector<double> exact;
        if (clipped) exact = roots(torus_along(ray, R, r), clipped->min, clipped->max);
        const auto got = s.intersect(ray, {});
        if (!exact.empty()) {
            ASSERT_TRUE(got) << "ray " << i << " missed the root at " << exact.front();
            EXPECT_NEAR(got->t, exact.front(), s.tolerance) << "ray " << i;
            ++hits;
            if (exact.size() == 4) ++inner_hits;
        } else if (got) {
            const Point3 p = ray.at(got->t);
            const double ring = std::hypot(std::hypot(p.x, p.z) - R, p.y) - r;
            EXPECT_NEAR(ring, 0, s.tolerance) << "ray " << i;
        }
    }
    EXPECT_GT(hits, 300);
    EXPECT_GT(inner_hits, 20);  // rays crossing the hole, with four roots
}

// A shell (x^2 + y^2 + z^2 - 1)^2 - e^2 < 0 of thickness about e = 1.5 x tolerance: each ray
// of a grid that crosses it is found, at its entry into the outer sphere r^2 = 1 + e, including
// rays that only graze the shell and never reach its inner sphere.
TEST(ImplicitSurface, ThinShellIsNeverMissed) {
    const double e = 1.5e-4;
    ImplicitSurface s = surface("(x^2 + y^2 + z^2 - 1)^2 - e^2", cube(1.2f), {{"e", e}});
    const double outer = std::sqrt(1 + e), inner = std::sqrt(1 - e);
    int grazing = 0;
    const auto check = [&](float x, float y) {
        const Ray ray{{x, y, -3}, {0, 0, 1}};
        const double h2 = double(x) * x + double(y) * y;
        const auto hit = s.intersect(ray, {});
        if (h2 < outer * outer) {
            ASSERT_TRUE(hit) << "missed at " << x << ", " << y;
            EXPECT_NEAR(hit->t, 3 - std::sqrt(outer * outer - h2), s.tolerance);
            if (h2 > inner * inner) ++grazing;
        } else if (h2 > (outer + 1e-3) * (outer + 1e-3)) {
            EXPECT_FALSE(hit) << "false hit at " << x << ", " << y;
        }
    };
    for (int i = 0; i <= 40; ++i)
        for (int j = 0; j <= 40; ++j) check(-1.1f + 0.055f * i, -1.1f + 0.055f * j);
    // Rays through the shell's rim: between the spheres, tangent to neither.
    for (int k = 0; k <= 20; ++k) check(float(inner + (outer - inner) * k / 20.0), 0);
    EXPECT_GE(grazing, 15);
}

TEST(ImplicitSurface, FeatureThinnerThanTheToleranceIsStillFound) {
    // A shell of thickness 1e-5, a tenth of the tolerance: found as a tangential hit.
    ImplicitSurface s = surface("(x^2 + y^2 + z^2 - 1)^2 - 1e-10", cube(1.2f));
    const auto search = find_first_root(s, {{0.3f, 0.2f, -3}, {0, 0, 1}}, {});
    ASSERT_TRUE(search.hit);
    EXPECT_NEAR(search.hit->t, 3 - std::sqrt(1 - 0.13), s.tolerance);
}

TEST(ImplicitSurface, TangentRays) {
    // Asymmetric, so that no midpoint of the subdivision falls exactly on the double root.
    const ImplicitSurface s =
        surface("x^2 + y^2 + z^2 - 1", {{-1.5f, -1.5f, -1.5f}, {1.5f, 1.5f, 1.7f}});
    // Touching the sphere at (1, 0, 0): a double root of f(t) = (t - 3)^2, no sign change.
    const auto touching = find_first_root(s, {{1, 0, -3}, {0, 0, 1}}, {});
    ASSERT_TRUE(touching.hit);
    EXPECT_EQ(touching.found, ImplicitSearch::Found::kTangential);
    EXPECT_NEAR(touching.hit->t, 3, s.tolerance);
    EXPECT_TRUE(s.intersect({{0.99999f, 0, -3}, {0, 0, 1}}, {}));
    // Passing 1e-3 above it: min f = 2e-3, far from any tolerance-wide enclosure of 0.
    EXPECT_FALSE(s.intersect({{1.001f, 0, -3}, {0, 0, 1}}, {}));
}

TEST(ImplicitSurface, RayFromInsideAndTheTRange) {
    const ImplicitSurface s = surface("x^2 + y^2 + z^2 - 1", cube(1.5f));
    const Ray inside{{0, 0, 0}, {1, 0, 0}};
    const auto hit = s.intersect(inside, {});
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit->t, 1);
    EXPECT_EQ(s.surface_at(inside, *hit).normal, (Normal3{1, 0, 0}));  // outwards
    const Ray through{{0, 0, -3}, {0, 0, 1}};
    EXPECT_FALSE(s.intersect(through, {0, 1.9f}));                   // ends before
    EXPECT_FLOAT_EQ(s.intersect(through, {2.5f, kInfinity})->t, 4);  // the far side
    EXPECT_FALSE(s.intersect({{0, 0, -3}, {0, 0, -1}}, {}));         // pointing away
}

TEST(ImplicitSurface, OnlyTheRegionCounts) {
    // The plane y = 0.5 is cut to the region: a ray meeting it outside misses.
    const ImplicitSurface s = surface("y - 0.5", cube(1));
    EXPECT_TRUE(s.intersect({{0, -3, 0}, {0, 1, 0}}, {}));
    EXPECT_FALSE(s.intersect({{2, -3, 0}, {0, 1, 0}}, {}));
    EXPECT_EQ(s.bounds().min, (Point3{-1, -1, -1}));
}

TEST(ImplicitSurface, GyroidLikeSurfaceHitsWhereFChangesSign) {
    const ImplicitSurface s = surface("sin(x) + sin(y) + sin(z)", cube(3));
    RandomRays rays({0, 0, 0}, 3, 11);
    for (int i = 0; i < 200; ++i) {
        const Ray ray = rays.next();
        const auto hit = s.intersect(ray, {});
        if (!hit) continue;
        const Point3 p = ray.at(hit->t);
        EXPECT_NEAR(std::sin(p.x) + std::sin(p.y) + std::sin(p.z), 0, 1e-5);
    }
}

// Expressions that are singular, undefined, enormous or wildly oscillating: every search
// ends, within its budget, and any hit is a finite t.
TEST(ImplicitSurface, HostileExpressionsNeitherCrashNorHang) {
    const char* hostile[] = {
        "1/(x - 0.5)",                      // a pole, no root
        "1/(x - 0.5)^2 + 1",                // a pole of even order
        "sqrt(-1 - x^2)",                   // undefined everywhere
        "sqrt(x) * 0 + log(-x)",            // the two halves of the domain never meet
        "exp(exp(exp(x))) - 1e10",          // huge values, a root at x = 1.1434
        "x*1e300*1e300",                    // overflows on both sides of its root x = 0
        "x/x - 1",                          // zero except at the 0/0 of x = 0
        "x - x",                            // zero everywhere
        "sin(1/x)",                         // infinitely many roots near x = 0
        "sin(1000*x) + cos(1000*x) + 1.5",  // no root, out of budget
        "(x^2 + y^2 + z^2 - 1)^64",         // a root of order 64
        "log(0*x)",                         // -inf everywhere
        "x^y^z",                            // negative bases to fractional powers
        "1e-300 * (x^2 + y^2 + z^2 - 1)",   // tiny but honest
    };
    RandomRays rays({0, 0, 0}, 1, 5);
    for (const char* source : hostile) {
        const ImplicitSurface s = surface(source, cube(2));
        const auto start = std::chrono::steady_clock::now();
        for (int i = 0; i < 20; ++i) {
            const Ray ray = i < 2 ? Ray{{-3, 0.1f, 0.2f}, {1, 0, 0}} : rays.next();
            const ImplicitSearch search = find_first_root(s, ray, {});
            EXPECT_LE(search.segments, s.max_segments) << source;
            if (search.hit) {
                EXPECT_TRUE(std::isfinite(search.hit->t)) << source;
                const SurfacePoint sp = s.surface_at(ray, *search.hit);
                EXPECT_NEAR(length(to_vector(sp.normal)), 1, 1e-5) << source;
            }
        }
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        EXPECT_LT(seconds, 5) << source;  // a hang guard, not a benchmark
    }
}

TEST(ImplicitSurface, HostileExpressionsGiveTheRightAnswers) {
    const Ray along_x{{-3, 0.1f, 0.2f}, {1, 0, 0}};  // x = t - 3
    const auto first = [&](const char* source) {
        return find_first_root(surface(source, cube(2)), along_x, {});
    };
    EXPECT_FALSE(first("1/(x - 0.5)").hit);  // the sign change at the pole is not a root
    EXPECT_FALSE(first("sqrt(-1 - x^2)").hit);
    EXPECT_FALSE(first("sqrt(x) * 0 + log(-x)").hit);
    EXPECT_NEAR(first("1/(x - 0.5) - 1").hit.value_or(ShapeHit{}).t, 4.5, 1e-4);  // x = 1.5
    EXPECT_NEAR(first("exp(exp(exp(x))) - 1e10").hit.value_or(ShapeHit{}).t,
                3 + std::log(std::log(std::log(1e10))), 1e-4);
    EXPECT_NEAR(first("x*1e300*1e300").hit.value_or(ShapeHit{}).t, 3, 1e-4);
    EXPECT_NEAR(first("x - x").hit.value_or(ShapeHit{}).t, 1, 1e-4);  // the region's edge
    // sin over any wide piece encloses [-1, 1], so f >= 0.001 is proven at once.
    const ImplicitSearch proven = first("sin(1000*x) + 1.001");
    EXPECT_FALSE(proven.hit);
    EXPECT_EQ(proven.found, ImplicitSearch::Found::kNothing);
    EXPECT_EQ(proven.segments, 1);
    // sin + cos >= -sqrt 2: f >= 0.086, but the two enclosures cannot know that they peak
    // apart, so each of the ~640 dips along the ray is searched down to small pieces, more than
    // the budget allows: a miss, after exactly max_segments pieces.
    const ImplicitSearch costly = first("sin(1000*x) + cos(1000*x) + 1.5");
    EXPECT_FALSE(costly.hit);
    EXPECT_EQ(costly.found, ImplicitSearch::Found::kExhausted);
    EXPECT_EQ(costly.segments, 4096);
    // The same dips at a tenth of the frequency are all proven root-free within the budget.
    const ImplicitSearch slower = first("sin(100*x) + cos(100*x) + 1.5");
    EXPECT_FALSE(slower.hit);
    EXPECT_EQ(slower.found, ImplicitSearch::Found::kNothing);
}

// What the tolerance means: f = sin(1000x) + cos(1000x) + 1.415 never reaches 0 (its minimum is
// 1.415 - sqrt 2 = 0.0008), but it changes by up to 0.14 over a tolerance-wide piece, and no
// enclosure of f over such a piece can exclude 0: it is a tangential hit. A resolution limit,
// documented, not a bug: a finer tolerance (1e-6) proves the same ray root-free.
TEST(ImplicitSurface, NearMissesWithinTheToleranceAreHits) {
    ImplicitSurface s = surface("sin(1000*x) + cos(1000*x) + 1.415", cube(2));
    const Ray ray{{-3, 0.1f, 0.2f}, {1, 0, 0}};
    const ImplicitSearch coarse = find_first_root(s, ray, {});
    ASSERT_TRUE(coarse.hit);
    EXPECT_EQ(coarse.found, ImplicitSearch::Found::kTangential);
    s.tolerance = 1e-6f;
    s.max_segments = 100000;
    const ImplicitSearch fine = find_first_root(s, ray, {0, 1.1f});  // the first few dips
    EXPECT_FALSE(fine.hit);
    EXPECT_EQ(fine.found, ImplicitSearch::Found::kNothing);
}

TEST(ImplicitSurface, BudgetBoundsTheWork) {
    ImplicitSurface s = surface("x^2 + y^2 + z^2 - 1", cube(1.5f));
    s.max_segments = 2;  // the worked example needs 3
    const ImplicitSearch search = find_first_root(s, {{0, 0, -3}, {0, 0, 1}}, {});
    EXPECT_FALSE(search.hit);
    EXPECT_EQ(search.found, ImplicitSearch::Found::kExhausted);
    EXPECT_EQ(search.segments, 2);
}

TEST(ImplicitSurface, BadRaysMiss) {
    const ImplicitSurface s = surface("x^2 + y^2 + z^2 - 1", cube(1.5f));
    const float nan = std::nanf("");
    EXPECT_FALSE(s.intersect({{nan, 0, -3}, {0, 0, 1}}, {}));
    EXPECT_FALSE(s.intersect({{0, 0, -3}, {0, 0, nan}}, {}));
    EXPECT_FALSE(s.intersect({{0, 0, -3}, {0, 0, 0}}, {}));
}

TEST(ImplicitSurface, ParameterChecks) {
    ImplicitSurface s = surface("x", cube(1));
    EXPECT_EQ(describe_problem(s), "");
    s.tolerance = 0;
    EXPECT_EQ(describe_problem(s), "implicit surface tolerance must be > 0, got 0");
    s.tolerance = 1e-4f;
    s.region = Bounds3{};
    EXPECT_EQ(describe_problem(s), "implicit surface bounds must be a finite, non-empty box");
    s.region = {{-1, -1, -1}, {kInfinity, 1, 1}};
    EXPECT_NE(describe_problem(s), "");
    s.region = cube(1);
    s.max_segments = 0;
    EXPECT_EQ(describe_problem(s), "implicit surface max_segments must be >= 1, got 0");
    s.f = nullptr;
    EXPECT_EQ(describe_problem(s), "implicit surface needs a function");
}

// A region that encloses the surface leaves the solid f < 0 closed; one that cuts through it
// leaves it open, and the search of the box's faces finds a point of the cut.
TEST(ImplicitSurface, RegionsThatCutTheSurfaceOpenAreFound) {
    const auto expect_cut = [](const ImplicitSurface& s) {
        const auto cut = point_cut_open(s);
        ASSERT_TRUE(cut);
        EXPECT_LT(s.f->value(*cut), 0);
        const bool on_boundary = cut->x == s.region.min.x || cut->x == s.region.max.x ||
                                 cut->y == s.region.min.y || cut->y == s.region.max.y ||
                                 cut->z == s.region.min.z || cut->z == s.region.max.z;
        EXPECT_TRUE(on_boundary);
        EXPECT_TRUE(s.region.contains(*cut));
    };
    const char* const ball = "x^2 + y^2 + z^2 - 1";
    EXPECT_FALSE(point_cut_open(surface(ball, cube(1.2f))));
    EXPECT_FALSE(point_cut_open(surface(ball, cube(1))));  // touching the faces is not cutting
    expect_cut(surface(ball, cube(0.9f)));
    expect_cut(surface(ball, {{0, -2, -2}, {2, 2, 2}}));  // half of it
    // A thin ball on one face, cut as a disk 0.08 across on a face 3 across: found by halving,
    // as a disk wider than the finest squares' diagonal holds one of their centres.
    expect_cut(surface("min(x^2 + y^2 + z^2 - 1, (x - 1.5)^2 + (y - 0.3)^2 + (z - 0.2)^2 - 0.04^2)",
                       cube(1.5f)));
    // f < 0 everywhere outside a ball: the box cuts the (unbounded) solid on every face.
    expect_cut(surface("1 - x^2 - y^2 - z^2", cube(2)));
}

TEST(ImplicitSurface, ShapePropertiesOfASphere) {
    const ImplicitSurface s =
        surface("(x - 0.2)^2 + (y + 0.1)^2 + (z - 0.3)^2 - 1.1^2", cube(1.6f));
    PropertyOptions options;
    options.convex = true;
    options.surface_tolerance = s.tolerance;
    options.normal_matches_gradient = true;
    expect_shape_properties(
        s,
        [](Point3 p) {
            return distance(p, Point3{0.2f, -0.1f, 0.3f}) - 1.1f;
        },
        RandomRays({0, 0, 0}, 1.5f), options);
}

TEST(ImplicitSurface, ShapePropertiesOfATorus) {
    const ImplicitSurface s = surface("(x^2 + y^2 + z^2 + 1 - 0.16)^2 - 4*(x^2 + z^2)",
                                      {{-1.5f, -0.5f, -1.5f}, {1.5f, 0.5f, 1.5f}});
    PropertyOptions options;
    options.surface_tolerance = s.tolerance;
    options.normal_matches_gradient = true;
    expect_shape_properties(
        s, [](Point3 p) { return std::hypot(std::hypot(p.x, p.z) - 1.0f, p.y) - 0.4f; },
        RandomRays({0, 0, 0}, 1.5f), options);
}

}  // namespace
}  // namespace glint
