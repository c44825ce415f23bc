// Ray-shape intersection kernels, each beside a reference on the same rays. The sphere pits the
// lecture notes' geometric method (early exits) against the algebraic quadratic of the English
// notes; the watertight triangle test, against the Moeller-Trumbore it replaced. Ratios are
// recorded in bench/README.md.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

#include "glint/geometry/shape.h"
#include "glint/geometry/watertight_triangle.h"
#include "glint/math/quadratic.h"

namespace glint {
namespace {

// Rays from around the shape towards a region twice its size: about half of them hit.
std::vector<Ray> make_rays(std::size_t n) {
    std::mt19937 rng(1);
    std::uniform_real_distribution<float> u(-1, 1);
    std::vector<Ray> rays;
    while (rays.size() < n) {
        const Vector3 d{u(rng), u(rng), u(rng)};
        if (length_squared(d) > 1 || length_squared(d) < 1e-3f) continue;
        const Point3 origin = Point3{0, 0, 0} + normalize(d) * 6;
        const Point3 aim{u(rng) * 2, u(rng) * 2, u(rng) * 2};
        rays.push_back({origin, normalize(aim - origin)});
    }
    return rays;
}

const std::vector<Ray>& rays() {
    static const std::vector<Ray> r = make_rays(4096);
    return r;
}

// The reference: substitute the ray into |P - C|^2 = r^2 and solve a t^2 + b t + c = 0.
std::optional<ShapeHit> algebraic_sphere(const Sphere& s, const Ray& ray, Interval t_range) {
    const Vector3 oc = ray.origin - s.center;
    const auto roots =
        solve_quadratic(dot(ray.direction, ray.direction), 2 * dot(oc, ray.direction),
                        dot(oc, oc) - s.radius * s.radius);
    if (!roots) return std::nullopt;
    if (t_range.contains(roots->t0)) return ShapeHit{roots->t0};
    if (t_range.contains(roots->t1)) return ShapeHit{roots->t1};
    return std::nullopt;
}

// The reference: Moeller and Trumbore (1997), glint's triangle test before the watertight one.
// Fast, but a ray through an edge that two triangles share can pass between them. Not inlined,
// so that it is called as the watertight test is (from another file).
[[gnu::noinline]] std::optional<ShapeHit> moller_trumbore(const Triangle& tri, const Ray& ray,
                                                          Interval t_range) {
    const auto& [v0, v1, v2] = tri.vertices;
    const Vector3 e1 = v1 - v0;
    const Vector3 e2 = v2 - v0;
    const Vector3 p = cross(ray.direction, e2);
    const float det = dot(e1, p);
    if (det == 0 || !std::isfinite(det)) return std::nullopt;
    const float inv_det = 1 / det;
    const Vector3 s = ray.origin - v0;
    const float b1 = dot(s, p) * inv_det;
    if (b1 < 0 || b1 > 1) return std::nullopt;
    const Vector3 q = cross(s, e1);
    const float b2 = dot(ray.direction, q) * inv_det;
    if (b2 < 0 || b1 + b2 > 1) return std::nullopt;
    const float t = dot(e2, q) * inv_det;
    if (!t_range.contains(t)) return std::nullopt;
    return ShapeHit{t, b1, b2};
}

template <typename Intersect>
void run(benchmark::State& state, Intersect intersect_one) {
    std::size_t hits = 0;
    for (auto _ : state) {
        for (const Ray& ray : rays()) hits += intersect_one(ray).has_value();
        benchmark::DoNotOptimize(hits);
    }
    state.SetItemsProcessed(state.iterations() * rays().size());
}

const Sphere kSphere{{0.1f, -0.2f, 0.05f}, 1};

void BM_SphereGeometric(benchmark::State& state) {
    run(state, [](const Ray& r) { return kSphere.intersect(r, {}); });
}
void BM_SphereAlgebraicReference(benchmark::State& state) {
    run(state, [](const Ray& r) { return algebraic_sphere(kSphere, r, {}); });
}
const Triangle kTriangle{{Point3{-1, -1, 0}, Point3{1, -1, 0.2f}, Point3{0, 1, -0.1f}}};

void BM_TriangleWatertight(benchmark::State& state) {
    run(state, [](const Ray& r) { return kTriangle.intersect(r, {}); });
}
// The shear computed once a ray, as a traversal could, to show what computing it per call costs.
void BM_TriangleWatertightShearedOnce(benchmark::State& state) {
    std::vector<RayShear> shears;
    for (const Ray& r : rays()) shears.emplace_back(r.direction);
    const auto& [v0, v1, v2] = kTriangle.vertices;
    std::size_t i = 0;
    run(state, [&](const Ray& r) {
        if (i == shears.size()) i = 0;
        return intersect_watertight(v0, v1, v2, r, shears[i++], {});
    });
}
void BM_TriangleMollerTrumboreReference(benchmark::State& state) {
    run(state, [](const Ray& r) { return moller_trumbore(kTriangle, r, {}); });
}
void BM_BoxSlabs(benchmark::State& state) {
    const Box b{{-1, -0.8f, -0.9f}, {0.9f, 1, 1}};
    run(state, [&](const Ray& r) { return b.intersect(r, {}); });
}
void BM_ShapeVariantDispatchSphere(benchmark::State& state) {
    const Shape shape = kSphere;
    run(state, [&](const Ray& r) { return intersect(shape, r, {}); });
}

BENCHMARK(BM_SphereGeometric);
BENCHMARK(BM_SphereAlgebraicReference);
BENCHMARK(BM_ShapeVariantDispatchSphere);
BENCHMARK(BM_TriangleWatertight);
BENCHMARK(BM_TriangleWatertightShearedOnce);
BENCHMARK(BM_TriangleMollerTrumboreReference);
BENCHMARK(BM_BoxSlabs);

}  // namespace
}  // namespace glint

BENCHMARK_MAIN();
