// Each shape's own area() and sample(u), the contract lights are made of: the areas with worked
// numbers, every point on the surface with the shape's own normal there, and the points spread
// by area (each part of a shape gets its share).
#include <gtest/gtest.h>

#include <cmath>

#include "glint/geometry/shape.h"
#include "glint/math/constants.h"
#include "glint/sampling/random.h"

namespace glint {
namespace {

Point2 u_of(int i) { return {random_float(i, 7, 0, 1), random_float(i, 7, 1, 1)}; }

Polygon polygon(std::vector<Point3> vertices) {
    return std::get<Polygon>(make_polygon(std::move(vertices)));
}

// A ray from just off the point back towards it hits the shape there, with the sample's normal
// (up to side).
template <class S>
void expect_on_surface(const S& shape, int count = 500) {
    for (int i = 0; i < count; ++i) {
        const SurfaceSample s = shape.sample(u_of(i));
        ASSERT_NEAR(length(to_vector(s.normal)), 1, 1e-5);
        EXPECT_FLOAT_EQ(s.pdf, 1 / shape.area());
        const Vector3 n = to_vector(s.normal);
        const Ray ray{s.p + n * 1e-2f, -n};
        const auto hit = shape.intersect(ray, {0, 1});
        ASSERT_TRUE(hit) << "point " << i;
        EXPECT_NEAR(hit->t, 1e-2f, 1e-4f) << "point " << i;
        const SurfacePoint sp = shape.surface_at(ray, *hit);
        EXPECT_NEAR(std::abs(dot(to_vector(sp.normal), n)), 1, 1e-4) << "point " << i;
    }
}

TEST(ShapeSampling, AreasWithWorkedNumbers) {
    EXPECT_FLOAT_EQ((Sphere{{0, 0, 0}, 2}).area(), 16 * kPi);
    EXPECT_FLOAT_EQ((Disk{{0, 0, 0}, {0, 1, 0}, 2, 1}).area(), 3 * kPi);  // pi (4 - 1)
    const Triangle triangle{{{{0, 0, 0}, {3, 0, 0}, {0, 4, 0}}}};
    EXPECT_FLOAT_EQ(triangle.area(), 6);
    EXPECT_FLOAT_EQ((Box{{0, 0, 0}, {1, 2, 3}}).area(), 22);  // 2 (2 + 6 + 3)
    // Side 2 pi r h = 4 pi, caps 2 pi r^2 = 2 pi.
    EXPECT_FLOAT_EQ((Cylinder{{0, 0, 0}, {0, 2, 0}, 1, true}).area(), 6 * kPi);
    EXPECT_FLOAT_EQ((Cylinder{{0, 0, 0}, {0, 2, 0}, 1, false}).area(), 4 * kPi);
    // A house: the unit square under a roof of height 1/2 over it: 1 + 1/4.
    EXPECT_FLOAT_EQ(polygon({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0.5f, 1.5f, 0}, {0, 1, 0}}).area(),
                    1.25f);
}

TEST(ShapeSampling, PointsLieOnTheSurfaceWithItsNormal) {
    expect_on_surface(Sphere{{1, 2, 3}, 2});
    expect_on_surface(Disk{{1, 0, 0}, Normal3(normalize(Vector3{1, 2, 3})), 2, 0});
    expect_on_surface(Disk{{1, 0, 0}, {0, 0, 1}, 2, 0.5f});
    expect_on_surface(Triangle{{{{0, 0, 0}, {3, 0, 1}, {0, 4, 2}}}});
    expect_on_surface(Box{{0, 0, 0}, {1, 2, 3}});
    expect_on_surface(Cylinder{{0, 0, 0}, {1, 2, 0}, 0.5f, true});
    expect_on_surface(polygon({{0, 0, 0}, {2, 0, 0}, {3, 1, 0}, {0, 1, 0}}));  // parallelogram
    expect_on_surface(polygon({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0.5f, 1.5f, 0}, {0, 1, 0}}));
}

// The fraction of n points for which `in` holds.
template <class S, class F>
double fraction(const S& shape, F in, int n = 20000) {
    int count = 0;
    for (int i = 0; i < n; ++i) count += in(shape.sample(u_of(i)).p) ? 1 : 0;
    return double(count) / n;
}

// Within 4 standard errors of a binomial share p over 20000 points.
void expect_share(double measured, double p) {
    EXPECT_NEAR(measured, p, 4 * std::sqrt(p * (1 - p) / 20000));
}

TEST(ShapeSampling, EachPartGetsItsShareOfTheArea) {
    // The box's two faces across z (1 x 2 each) hold 4 / 22 of its area.
    const Box box{{0, 0, 0}, {1, 2, 3}};
    expect_share(fraction(box, [](Point3 p) { return p.z == 0 || p.z == 3; }), 4.0 / 22);
    // The cylinder's caps 2 pi of 6 pi.
    const Cylinder can{{0, 0, 0}, {0, 2, 0}, 1, true};
    expect_share(fraction(can, [](Point3 p) { return p.y == 0 || p.y == 2; }), 1.0 / 3);
    // The house's roof 1/4 of 5/4; the square's left half 1/2 of 5/4.
    const Polygon house = polygon({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0.5f, 1.5f, 0}, {0, 1, 0}});
    expect_share(fraction(house, [](Point3 p) { return p.y > 1; }), 0.2);
    expect_share(fraction(house, [](Point3 p) { return p.y < 1 && p.x < 0.5f; }), 0.4);
    // The ring between radii 1 and 2 holds (1.5^2 - 1) / 3 of its area within radius 1.5.
    const Disk ring{{0, 0, 0}, {0, 0, 1}, 2, 1};
    expect_share(fraction(ring, [](Point3 p) { return length(to_vector(p)) < 1.5f; }), 1.25 / 3);
    // A full disk's concentric map: a quarter within half the radius.
    const Disk disk{{0, 0, 0}, {0, 0, 1}, 2, 0};
    expect_share(fraction(disk, [](Point3 p) { return length(to_vector(p)) < 1; }), 0.25);
    // A sphere: the cap above y = 1 of radius 2 holds (2 - 1) / 4 of it (Archimedes).
    const Sphere sphere{{0, 0, 0}, 2};
    expect_share(fraction(sphere, [](Point3 p) { return p.y > 1; }), 0.25);
}

TEST(ShapeSampling, ConcavePolygonsAreNotConvex) {
    EXPECT_TRUE(is_convex(polygon({{0, 0, 0}, {2, 0, 0}, {3, 1, 0}, {0, 1, 0}})));
    EXPECT_FALSE(is_convex(polygon({{0, 0, 0}, {2, 1, 0}, {0, 2, 0}, {1, 1, 0}})));
}

}  // namespace
}  // namespace glint
