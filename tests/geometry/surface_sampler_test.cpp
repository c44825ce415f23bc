// Points drawn on shapes: on the surface, with the right normal, and with a density that
// integrates to one over the surface (the mean of 1 / pdf is the area).
#include "glint/geometry/surface_sampler.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <memory>

#include "glint/geometry/shape.h"
#include "glint/math/constants.h"
#include "glint/sampling/random.h"

namespace glint::surface_sampler_test {
namespace {

Point2 u_of(int i) { return {random_float(i, 0, 0, 1), random_float(i, 0, 1, 1)}; }

// The mean of 1 / pdf over n points: the surface's area when the pdf is right.
double mean_inverse_pdf(const SurfaceSampler& sampler, int n) {
    double sum = 0;
    for (int i = 0; i < n; ++i) sum += 1 / double(sampler.sample(u_of(i)).pdf);
    return sum / n;
}

TEST(SurfaceSampler, SpherePointsLieOnItWithOutwardNormals) {
    const auto sampler = SurfaceSampler::of(Sphere{{1, 2, 3}, 2});
    ASSERT_TRUE(sampler);
    for (int i = 0; i < 1000; ++i) {
        const SurfaceSample s = sampler->sample(u_of(i));
        EXPECT_NEAR(distance(s.p, {1, 2, 3}), 2, 1e-5);
        EXPECT_NEAR(dot(s.normal, (s.p - Point3{1, 2, 3}) / 2), 1, 1e-5);
        EXPECT_FLOAT_EQ(s.pdf, 1 / (16 * kPi));
    }
}

TEST(SurfaceSampler, ASphereSeenFromAPointIsDrawnOverItsConeOfDirections) {
    // Seen from the origin, the sphere of radius 1 at distance 2 fills the cone of half-angle
    // 30 degrees: solid angle 2 pi (1 - cos 30). Every point lies on the visible side, and
    // cos / (d^2 pdf) is that solid angle for each of them.
    const Point3 center{0, 2, 0};
    const auto sampler = SurfaceSampler::of(Sphere{center, 1});
    ASSERT_TRUE(sampler);
    const double solid_angle = 2 * kPi * (1 - std::sqrt(3.0) / 2);
    for (int i = 0; i < 1000; ++i) {
        const SurfaceSample s = sampler->sample_seen_from({0, 0, 0}, u_of(i));
        EXPECT_NEAR(distance(s.p, center), 1, 1e-5);
        const Vector3 to_origin = Point3{0, 0, 0} - s.p;
        const float d = length(to_origin);
        const float cos_at_point = dot(s.normal, to_origin / d);
        EXPECT_GE(cos_at_point, -1e-5f);
        EXPECT_NEAR(std::abs(cos_at_point) / (d * d * s.pdf), solid_angle, 1e-3);
    }
    // From inside, and for other shapes, the points are drawn by area.
    EXPECT_FLOAT_EQ(sampler->sample_seen_from(center, u_of(0)).pdf, 1 / (4 * kPi));
}

TEST(SurfaceSampler, BoxFacesAreDrawnByTheirArea) {
    // 1 x 2 x 3: faces of 6 (x), 3 (y) and 2 (z) each, 22 in all.
    const auto sampler = SurfaceSampler::of(Box{{0, 0, 0}, {1, 2, 3}});
    ASSERT_TRUE(sampler);
    std::map<int, int> by_axis;
    const int n = 22000;
    for (int i = 0; i < n; ++i) {
        const SurfaceSample s = sampler->sample(u_of(i));
        EXPECT_FLOAT_EQ(s.pdf, 1 / 22.0f);
        const int axis = std::abs(s.normal.x) == 1 ? 0 : std::abs(s.normal.y) == 1 ? 1 : 2;
        ++by_axis[axis];
        // On the face the normal names.
        const float coordinate = s.p[axis], side = s.normal[axis] > 0 ? (axis + 1.0f) : 0.0f;
        EXPECT_NEAR(coordinate, side, 1e-5);
    }
    EXPECT_NEAR(by_axis[0], n * 12 / 22, 250);
    EXPECT_NEAR(by_axis[1], n * 6 / 22, 250);
    EXPECT_NEAR(by_axis[2], n * 4 / 22, 250);
}

TEST(SurfaceSampler, DiskTriangleAndCylinderDensitiesIntegrateToTheirAreas) {
    EXPECT_NEAR(mean_inverse_pdf(*SurfaceSampler::of(Disk{{0, 0, 0}, {0, 1, 0}, 2, 1}), 100),
                3 * kPi, 1e-4);
    const Triangle t{{Point3{0, 0, 0}, Point3{4, 0, 0}, Point3{0, 3, 0}}};
    EXPECT_NEAR(mean_inverse_pdf(*SurfaceSampler::of(t), 100), 6, 1e-4);
    // Side 2 pi r h = 2 pi * 3 plus two caps of pi.
    const Cylinder c{{0, 0, 0}, {0, 3, 0}, 1, true};
    EXPECT_NEAR(mean_inverse_pdf(*SurfaceSampler::of(c), 100), 8 * kPi, 1e-3);
}

TEST(SurfaceSampler, TransformsStretchTheDensity) {
    // A unit box scaled by (2, 3, 4): area 2 (6 + 12 + 8) = 52. Faces stretch by different
    // factors, so the density differs from face to face; its inverse still averages to the area.
    const auto placed = std::make_shared<const Shape>(Box{{0, 0, 0}, {1, 1, 1}});
    const Transformed scaled(Transform::scale(2, 3, 4), placed);
    const auto sampler = SurfaceSampler::of(scaled);
    ASSERT_TRUE(sampler);
    EXPECT_NEAR(mean_inverse_pdf(*sampler, 200000), 52, 0.3);
    const SurfaceSample s = sampler->sample({0.3f, 0.6f});
    EXPECT_NEAR(length(to_vector(s.normal)), 1, 1e-6);
    // A uniform scale keeps the density uniform: a sphere of radius 1 scaled by 3.
    const Transformed big(Transform::scale(3, 3, 3),
                          std::make_shared<const Shape>(Sphere{{0, 0, 0}, 1}));
    const SurfaceSample b = SurfaceSampler::of(big)->sample({0.2f, 0.7f});
    EXPECT_NEAR(b.pdf, 1 / (36 * kPi), 1e-7);
    EXPECT_NEAR(distance(b.p, {0, 0, 0}), 3, 1e-5);
}

TEST(SurfaceSampler, ConvexPolygonsAreDrawnOnConcaveOnesAndUnboundedShapesAreNot) {
    const auto square =
        make_polygon({{0, 0, 0}, {2, 0, 0}, {2, 0, 2}, {0, 0, 2}}, InsideTest::even_odd);
    const auto sampler = SurfaceSampler::of(std::get<Polygon>(square));
    ASSERT_TRUE(sampler);
    EXPECT_NEAR(mean_inverse_pdf(*sampler, 100), 4, 1e-5);
    const auto dart =
        make_polygon({{0, 0, 0}, {2, 0, 0}, {1, 0, 0.5f}, {1, 0, 2}}, InsideTest::even_odd);
    EXPECT_FALSE(SurfaceSampler::of(std::get<Polygon>(dart)));
    EXPECT_FALSE(SurfaceSampler::of(Plane{{0, 0, 0}, {0, 1, 0}}));
    EXPECT_FALSE(SurfaceSampler::of(Torus{}));
}

}  // namespace
}  // namespace glint::surface_sampler_test
