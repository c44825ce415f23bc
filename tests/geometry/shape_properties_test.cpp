// The shared property checks on the shapes of the Whitted scene.
#include <gtest/gtest.h>

#include <algorithm>

#include "glint/geometry/shape.h"
#include "shape_property_checks.h"

namespace glint {
namespace {

using testing::expect_shape_properties;
using testing::PropertyOptions;
using testing::RandomRays;

PropertyOptions convex() {
    PropertyOptions options;
    options.convex = true;
    options.normal_matches_gradient = true;
    return options;
}

TEST(ShapeProperties, Sphere) {
    const Sphere s{{0.2f, -0.1f, 0.3f}, 1.1f};
    expect_shape_properties(
        s, [&](Point3 p) { return distance(p, s.center) - s.radius; }, RandomRays({0, 0, 0}, 1.5f),
        convex());
}

TEST(ShapeProperties, Plane) {
    const Plane s{{0, 0.3f, 0}, Normal3(normalize(Vector3{0.2f, 1, -0.3f}))};
    expect_shape_properties(
        s, [&](Point3 p) { return dot(s.normal, p - s.point); }, RandomRays({0, 0, 0}, 1.5f),
        convex());
}

TEST(ShapeProperties, Triangle) {
    const Triangle s{{Point3{-1, -1, 0.2f}, Point3{1.5f, -0.5f, 0}, Point3{0, 1.2f, -0.3f}}};
    const Vector3 n =
        normalize(cross(s.vertices[1] - s.vertices[0], s.vertices[2] - s.vertices[0]));
    expect_shape_properties(
        s, [&](Point3 p) { return dot(n, p - s.vertices[0]); }, RandomRays({0, 0, 0}, 1.5f),
        convex());
}

TEST(ShapeProperties, Box) {
    const Box s{{-0.8f, -0.5f, -1}, {1, 0.7f, 0.4f}};
    // Signed: the largest of the six faces' plane functions, with a kink at the edges, where hits
    // within the difference step see two faces.
    const auto signed_box = [&](Point3 p) {
        float d = -kInfinity;
        for (int a = 0; a < 3; ++a) d = std::max({d, s.min[a] - p[a], p[a] - s.max[a]});
        return d;
    };
    PropertyOptions options = convex();
    options.gradient_mismatch_fraction = 0.02f;
    expect_shape_properties(s, signed_box, RandomRays({0, 0, 0}, 1.5f), options);
}

}  // namespace
}  // namespace glint
