// Invariants every shape keeps on random rays: the hit lies on the surface, the normal is unit
// length, and a ray leaving the surface does not hit it again.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "glint/geometry/shape.h"

namespace glint {
namespace {

// Signed or absolute distance of p from the shape's surface.
struct DistanceToSurface {
    Point3 p;
    float operator()(const Sphere& s) const { return distance(p, s.center) - s.radius; }
    float operator()(const Plane& s) const { return dot(s.normal, p - s.point); }
    float operator()(const Triangle& s) const {
        const Vector3 n =
            normalize(cross(s.vertices[1] - s.vertices[0], s.vertices[2] - s.vertices[0]));
        return dot(n, p - s.vertices[0]);
    }
    float operator()(const Box& s) const {
        float d = kInfinity;
        for (int a = 0; a < 3; ++a)
            d = std::min({d, std::abs(p[a] - s.min[a]), std::abs(p[a] - s.max[a])});
        return d;
    }
};

class ShapeProperties : public ::testing::TestWithParam<Shape> {
protected:
    std::mt19937 rng_{12345};
    std::uniform_real_distribution<float> unit_{-1, 1};

    Vector3 random_direction() {
        for (;;) {
            const Vector3 v{unit_(rng_), unit_(rng_), unit_(rng_)};
            if (const float l2 = length_squared(v); l2 > 1e-4f && l2 <= 1) return v / std::sqrt(l2);
        }
    }
    // A ray from a random point outside, aimed near the shape.
    Ray random_ray_towards(Point3 target) {
        const Point3 origin = target + random_direction() * 10;
        const Point3 aim = target + Vector3{unit_(rng_), unit_(rng_), unit_(rng_)} * 1.5f;
        return {origin, normalize(aim - origin)};
    }
};

TEST_P(ShapeProperties, HitsLieOnTheSurfaceWithUnitNormals) {
    const Shape& shape = GetParam();
    int hits = 0;
    for (int i = 0; i < 2000; ++i) {
        const Ray ray = random_ray_towards({0, 0, 0});
        const auto hit = intersect(shape, ray, {});
        if (!hit) continue;
        ++hits;
        const SurfacePoint sp = surface_at(shape, ray, *hit);
        EXPECT_NEAR(std::visit(DistanceToSurface{sp.p}, shape), 0, 1e-5f);
        EXPECT_NEAR(distance(sp.p, ray.at(hit->t)), 0, 1e-4f);
        EXPECT_NEAR(length(to_vector(sp.normal)), 1, 1e-5f);
        EXPECT_NEAR(length(to_vector(sp.shading_normal)), 1, 1e-5f);
        EXPECT_GT(dot(sp.normal, sp.shading_normal), 0);
    }
    EXPECT_GT(hits, 200);
}

TEST_P(ShapeProperties, RayLeavingTheSurfaceDoesNotHitItAgain) {
    const Shape& shape = GetParam();
    for (int i = 0; i < 2000; ++i) {
        const Ray ray = random_ray_towards({0, 0, 0});
        const auto hit = intersect(shape, ray, {});
        if (!hit) continue;
        const SurfacePoint sp = surface_at(shape, ray, *hit);
        // Leave on the side the ray came from, in a random direction of that hemisphere.
        const Normal3 n = face_forward(sp.normal, -ray.direction);
        Vector3 d = random_direction();
        if (dot(n, d) < 0) d = -d;
        const Ray leaving{sp.p + to_vector(n) * 1e-4f, d};
        EXPECT_FALSE(intersect(shape, leaving, {})) << "shape " << shape_name(shape);
    }
}

INSTANTIATE_TEST_SUITE_P(
    AllShapes, ShapeProperties,
    ::testing::Values(Shape{Sphere{{0.2f, -0.1f, 0.3f}, 1.1f}},
                      Shape{Plane{{0, 0.3f, 0}, Normal3(normalize(Vector3{0.2f, 1, -0.3f}))}},
                      Shape{Triangle{
                          {Point3{-1, -1, 0.2f}, Point3{1.5f, -0.5f, 0}, Point3{0, 1.2f, -0.3f}}}},
                      Shape{Box{{-0.8f, -0.5f, -1}, {1, 0.7f, 0.4f}}}),
    [](const ::testing::TestParamInfo<Shape>& param) {
        return std::string(shape_name(param.param));
    });

}  // namespace
}  // namespace glint
