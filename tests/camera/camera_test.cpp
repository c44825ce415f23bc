#include "glint/camera/camera.h"

#include <gtest/gtest.h>

#include <cmath>

#include "glint/math/constants.h"

namespace glint {
namespace {

void expect_near(Vector3 a, Vector3 b, float tol = 1e-6f) {
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
    EXPECT_NEAR(a.z, b.z, tol);
}

// Looking down +z with y up and a 90 degree vertical field of view on a 2:1 image, the window
// at distance 1 spans x' in [-2, 2] and y' in [-1, 1]. Right-handed: right = forward x up = -x.
TEST(Camera, CornerRaysOfThePerspectiveWindow) {
    CameraSpec spec;
    spec.from = {0, 0, 0}, spec.at = {0, 0, 1}, spec.up = {0, 1, 0}, spec.fov = 90;
    const Camera camera(spec, 200, 100);
    expect_near(camera.generate_ray({0, 0}).direction, normalize(Vector3{2, 1, 1}));
    expect_near(camera.generate_ray({200, 0}).direction, normalize(Vector3{-2, 1, 1}));
    expect_near(camera.generate_ray({0, 100}).direction, normalize(Vector3{2, -1, 1}));
    expect_near(camera.generate_ray({200, 100}).direction, normalize(Vector3{-2, -1, 1}));
    expect_near(camera.generate_ray({100, 50}).direction, {0, 0, 1});
    EXPECT_EQ(camera.generate_ray({0, 0}).origin, (Point3{0, 0, 0}));
}

TEST(Camera, CentreRayHitsLookAtAndFovIsTheFullVerticalAngle) {
    CameraSpec spec;
    spec.from = {1, 2, 3}, spec.at = {-2, 0.5f, 7}, spec.up = {0.2f, 1, 0.1f}, spec.fov = 40;
    const Camera camera(spec, 320, 240);
    const Ray centre = camera.generate_ray({160, 120});
    expect_near(centre.direction, normalize(spec.at - spec.from));
    const Vector3 top = camera.generate_ray({160, 0}).direction;
    const Vector3 bottom = camera.generate_ray({160, 240}).direction;
    EXPECT_NEAR(degrees(std::acos(dot(top, bottom))), 40, 1e-3);
    // The top of the image leans towards the given up vector.
    EXPECT_GT(dot(top - bottom, spec.up), 0);
}

TEST(Camera, OrthographicRaysAreParallelAndSpanTheViewHeight) {
    CameraSpec spec;
    spec.projection = Projection::orthographic;
    spec.from = {0, 0, 0}, spec.at = {0, 0, 1}, spec.height = 2;
    const Camera camera(spec, 200, 100);
    const Ray corner = camera.generate_ray({0, 0});
    EXPECT_EQ(corner.direction, (Vector3{0, 0, 1}));
    EXPECT_EQ(corner.origin, (Point3{2, 1, 0}));
    const Ray opposite = camera.generate_ray({200, 100});
    EXPECT_EQ(opposite.origin, (Point3{-2, -1, 0}));
}

}  // namespace
}  // namespace glint
