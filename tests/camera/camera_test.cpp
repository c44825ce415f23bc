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

// A view of its own shape, 1:2 on the same 2:1 image: the window spans x' in [-0.5, 0.5], and
// the image stretches it.
TEST(Camera, AViewOfItsOwnShapeIsStretchedOverTheImage) {
    CameraSpec spec;
    spec.from = {0, 0, 0}, spec.at = {0, 0, 1}, spec.up = {0, 1, 0}, spec.fov = 90;
    spec.aspect = 0.5f;
    const Camera camera(spec, 200, 100);
    expect_near(camera.generate_ray({0, 0}).direction, normalize(Vector3{0.5f, 1, 1}));
    expect_near(camera.generate_ray({200, 100}).direction, normalize(Vector3{-0.5f, -1, 1}));
}

// POV-Ray's cameras are left-handed: right = up x forward, so the same view is mirrored.
TEST(Camera, ALeftHandedCameraHasRightOnTheOtherSide) {
    CameraSpec spec;
    spec.from = {0, 0, 0}, spec.at = {0, 0, 1}, spec.up = {0, 1, 0}, spec.fov = 90;
    spec.left_handed = true;
    const Camera camera(spec, 200, 100);
    expect_near(camera.generate_ray({0, 0}).direction, normalize(Vector3{-2, 1, 1}));
    expect_near(camera.generate_ray({200, 100}).direction, normalize(Vector3{2, -1, 1}));
    // A point seen on the right of the image projects there.
    const auto seen = camera.connect({1, 0, 1}, {0.5f, 0.5f}, 0);
    ASSERT_TRUE(seen);
    EXPECT_NEAR(seen->film.x, 150, 1e-3);
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

namespace glint {
namespace {

// The wide projections on a 2:1 image of 200 x 100, looking down +z with y up and, being
// left-handed, x to the right: film (100, 50) is the view's centre.
CameraSpec wide(Projection projection, float fov) {
    CameraSpec spec;
    spec.from = {0, 0, 0}, spec.at = {0, 0, 1}, spec.up = {0, 1, 0};
    spec.left_handed = true;
    spec.projection = projection;
    spec.fov = fov;
    return spec;
}

constexpr float kHalfRoot2 = 0.70710678f;

// Equidistant: 90 degrees off the axis at the rim of the circle the height spans (film x 150
// is half the height right of the centre), 45 degrees half-way up; outside it, nothing.
TEST(Camera, FisheyeAnglesGrowWithTheDistanceFromTheCentre) {
    const Camera camera(wide(Projection::fisheye, 180), 200, 100);
    expect_near(camera.generate_ray({100, 50}).direction, {0, 0, 1});
    expect_near(camera.generate_ray({150, 50}).direction, {1, 0, 0});
    expect_near(camera.generate_ray({100, 25}).direction, {0, kHalfRoot2, kHalfRoot2});
    EXPECT_TRUE(camera.sees({150, 50}));
    EXPECT_FALSE(camera.sees({0, 0}));
    EXPECT_FALSE(camera.sees({151, 50}));
    EXPECT_TRUE(Camera(wide(Projection::perspective, 60), 200, 100).sees({0, 0}));
}

// Across the width 180 degrees (a quarter of the width is 45), the same degrees a pixel up.
TEST(Camera, UltraWideAngleTurnsBothWaysByAngles) {
    const Camera camera(wide(Projection::ultra_wide_angle, 180), 200, 100);
    expect_near(camera.generate_ray({150, 50}).direction, {kHalfRoot2, 0, kHalfRoot2});
    expect_near(camera.generate_ray({100, 0}).direction, {0, kHalfRoot2, kHalfRoot2});
}

// Half a turn from left to right, with right as long as the view is wide (2); up the tangent.
TEST(Camera, PanoramicSpansHalfATurnAcross) {
    const Camera camera(wide(Projection::panoramic, 90), 200, 100);
    expect_near(camera.generate_ray({0, 50}).direction, {-1, 0, 0}, 1e-5f);
    // 45 degrees right of the axis: cos 45 * 2 along x, sin 45 along z.
    expect_near(camera.generate_ray({150, 50}).direction, normalize(Vector3{2, 0, 1}));
    expect_near(camera.generate_ray({100, 25}).direction, {0, kHalfRoot2, kHalfRoot2}, 1e-5f);
}

// Round the vertical axis by the angle across, up as a perspective camera with a view 1 high
// at distance 1; parallel along it, from a point a quarter of the extent up; the axis across.
TEST(Camera, CylindricalTurnsRoundItsAxisAndGoesStraightAlongIt) {
    CameraSpec spec = wide(Projection::cylindrical, 180);
    spec.height = 1;
    expect_near(Camera(spec, 200, 100).generate_ray({150, 25}).direction,
                normalize(Vector3{kHalfRoot2, 0.25f, kHalfRoot2}));
    spec.cylinder_parallel = true;
    const Ray parallel = Camera(spec, 200, 100).generate_ray({150, 25});
    expect_near(parallel.direction, {kHalfRoot2, 0, kHalfRoot2});
    expect_near(to_vector(parallel.origin), {0, 0.25f, 0});
    spec.cylinder_parallel = false;
    spec.cylinder_axis_across = true;
    expect_near(Camera(spec, 200, 100).generate_ray({150, 25}).direction,
                normalize(Vector3{0.25f, kHalfRoot2, kHalfRoot2}));
}

// Longitude across the width (a quarter of 360 degrees right is +x), latitude up.
TEST(Camera, SphericalIsEquirectangular) {
    CameraSpec spec = wide(Projection::spherical, 360);
    spec.vertical_fov = 180;
    const Camera camera(spec, 200, 100);
    expect_near(camera.generate_ray({150, 50}).direction, {1, 0, 0}, 1e-6f);
    expect_near(camera.generate_ray({175, 50}).direction, {kHalfRoot2, 0, -kHalfRoot2}, 1e-6f);
    expect_near(camera.generate_ray({100, 25}).direction, {0, kHalfRoot2, kHalfRoot2}, 1e-6f);
    expect_near(camera.generate_ray({0, 50}).direction, {0, 0, -1}, 1e-6f);
}

Point2 lens_u(int i, int n) {  // an n x n grid of lens numbers
    return {(float(i % n) + 0.5f) / float(n), (float(i / n) + 0.5f) / float(n)};
}

// Where the ray meets the plane z = depth (the camera looks down +z from the origin).
Point3 at_depth(const Ray& r, float depth) { return r.at((depth - r.origin.z) / r.direction.z); }

CameraSpec lens_camera() {
    CameraSpec spec;
    spec.from = {0, 0, 0}, spec.at = {0, 0, 1}, spec.fov = 50;
    spec.lens.radius = 0.1f;
    spec.lens.focus_distance = 4;
    return spec;
}

TEST(Camera, ThinLensRaysMeetOnThePlaneOfFocus) {
    const Camera camera(lens_camera(), 64, 48);
    for (const Point2 film : {Point2{32, 24}, Point2{3, 40}, Point2{60, 5}}) {
        const Point3 sharp = at_depth(camera.generate_ray(film), 4);
        for (int i = 0; i < 64; ++i) {
            const Ray r = camera.generate_ray(film, lens_u(i, 8));
            EXPECT_NEAR(length(r.direction), 1, 1e-6f);
            const Point3 p = at_depth(r, 4);
            EXPECT_NEAR(distance(p, sharp), 0, 1e-5f);
            // Each ray starts on the aperture, a disk of radius 0.1 around the eye.
            EXPECT_NEAR(r.origin.z, 0, 1e-7f);
            EXPECT_LE(std::hypot(r.origin.x, r.origin.y), 0.1f + 1e-6f);
        }
    }
}

// The render loop works out a packet's aperture points before its rays: the same rays, bit for
// bit, as from the lens numbers in one go.
TEST(Camera, RaysFromApertureOrLensNumbersAreTheSame) {
    const Camera camera(lens_camera(), 64, 48);
    for (const Point2 film : {Point2{32, 24}, Point2{3, 40}}) {
        for (int i = 0; i < 16; ++i) {
            const Point2 u = lens_u(i, 4);
            const Ray a = camera.generate_ray(film, u);
            const Ray b = camera.generate_ray_from_aperture(film, camera.aperture_point(u), 0);
            EXPECT_EQ(a.origin, b.origin);
            EXPECT_EQ(a.direction, b.direction);
        }
    }
}

TEST(Camera, OffFocusPointsSpreadOverTheCircleOfConfusion) {
    // At depth z the rays through one film position spread over a disk of radius
    // r |z - f| / f around the pinhole ray: 0.1 * 4 / 4 = 0.1 at z = 8, 0.05 at z = 2.
    const Camera camera(lens_camera(), 64, 48);
    const Point2 film{20, 30};
    for (const auto& [depth, radius] : {std::pair{8.0f, 0.1f}, std::pair{2.0f, 0.05f}}) {
        const Point3 centre = at_depth(camera.generate_ray(film), depth);
        double farthest = 0, mean_square = 0;
        const int n = 64;
        for (int i = 0; i < n * n; ++i) {
            const double d =
                distance(at_depth(camera.generate_ray(film, lens_u(i, n)), depth), centre);
            farthest = std::max(farthest, d);
            mean_square += d * d / (n * n);
        }
        EXPECT_NEAR(farthest, radius, radius * 0.02);
        // Uniform over the disk: the mean square distance is radius^2 / 2.
        EXPECT_NEAR(mean_square, radius * radius / 2, radius * radius * 0.01);
    }
}

TEST(Camera, PolygonalApertureKeepsItsPointsInsideThePolygon) {
    CameraSpec spec = lens_camera();
    spec.lens.blades = 5;
    spec.lens.blade_rotation = 90;  // a vertex straight up
    const Camera camera(spec, 64, 48);
    const float apothem = std::cos(kPi / 5);
    float top = 0;
    for (int i = 0; i < 1024; ++i) {
        const Point2 a = camera.aperture_point(lens_u(i, 32));
        top = std::max(top, a.y);
        // Inside every edge: the distance along each edge's outward normal is at most the
        // apothem.
        for (int k = 0; k < 5; ++k) {
            const float mid = radians(90.0f) + (2 * k + 1) * kPi / 5;
            EXPECT_LE(a.x * std::cos(mid) + a.y * std::sin(mid), apothem + 1e-5f);
        }
    }
    EXPECT_GT(top, 0.9f);  // reaches towards the top vertex
}

TEST(Camera, ShutterTimesSpanTheIntervalAndAClosedShutterNeedsNoNumbers) {
    CameraSpec spec;
    EXPECT_FALSE(Camera(spec, 8, 8).has_shutter());
    EXPECT_FALSE(Camera(spec, 8, 8).has_lens());
    spec.shutter_open = 0.25f, spec.shutter_close = 0.75f;
    const Camera camera(spec, 8, 8);
    EXPECT_TRUE(camera.has_shutter());
    EXPECT_EQ(camera.shutter_time(0), 0.25f);
    EXPECT_EQ(camera.shutter_time(0.5f), 0.5f);
    EXPECT_EQ(camera.generate_ray({4, 4}, {0.5f, 0.5f}, 0.6f).time, 0.6f);
}

TEST(Camera, AMovingCameraIsEachKeyframesCameraAtItsTime) {
    CameraSpec spec;
    spec.fov = 60;
    spec.motion = {{0, {0, 0, 0}, {0, 0, 1}, {0, 1, 0}}, {1, {2, 0, 0}, {3, 1, 1}, {0, 1, 0}}};
    const Camera moving(spec, 40, 30);
    for (const int k : {0, 1}) {
        CameraSpec still = spec;
        still.motion.clear();
        still.from = spec.motion[k].from, still.at = spec.motion[k].at;
        const Camera fixed(still, 40, 30);
        for (const Point2 film : {Point2{0, 0}, Point2{20, 15}, Point2{33, 7}}) {
            const Ray a = moving.generate_ray(film, {0.5f, 0.5f}, float(k));
            const Ray b = fixed.generate_ray(film);
            expect_near(to_vector(a.origin), to_vector(b.origin), 1e-5f);
            expect_near(a.direction, b.direction, 1e-5f);
        }
    }
    // Halfway, the eye is halfway along its straight path.
    expect_near(to_vector(moving.generate_ray({20, 15}, {0.5f, 0.5f}, 0.5f).origin), {1, 0, 0},
                1e-5f);
}

// connect() inverts generate_ray(): a point on the ray of a film position and lens point lands
// back on that film position through that lens point, for a pinhole, a thin lens and a moving
// camera.
TEST(Camera, ConnectingAPointFindsTheFilmPositionAndLensPointOfItsRay) {
    CameraSpec spec;
    spec.from = {1, 2, -3}, spec.at = {0, 1, 0}, spec.up = {0, 1, 0}, spec.fov = 50;
    for (const float aperture : {0.0f, 0.3f}) {
        spec.lens.radius = aperture;
        spec.lens.focus_distance = 2.5f;
        const Camera camera(spec, 160, 90);
        for (const Point2 film : {Point2{80, 45}, Point2{10.5f, 80.25f}, Point2{150, 3}}) {
            const Point2 lens{0.3f, 0.8f};
            const Ray ray = camera.generate_ray(film, lens);
            const auto c = camera.connect(ray.at(4), lens, 0);
            ASSERT_TRUE(c);
            EXPECT_NEAR(c->film.x, film.x, 1e-3f) << aperture;
            EXPECT_NEAR(c->film.y, film.y, 1e-3f) << aperture;
            expect_near(to_vector(c->lens), to_vector(ray.origin), 1e-5f);
            expect_near(c->to_camera, -ray.direction, 1e-5f);
            EXPECT_NEAR(c->distance, 4, 1e-4f);
        }
        // Behind the camera: nothing.
        EXPECT_FALSE(camera.connect({2, 3, -6}, {0.5f, 0.5f}, 0));
    }
    CameraSpec moving = spec;
    moving.lens = {};
    moving.shutter_close = 1;
    moving.motion = {{0, {1, 2, -3}, {0, 1, 0}, {0, 1, 0}}, {1, {-1, 2, -3}, {0, 1, 0}, {0, 1, 0}}};
    const Camera camera(moving, 160, 90);
    const Ray ray = camera.generate_ray({40, 20}, {0.5f, 0.5f}, 0.7f);
    const auto c = camera.connect(ray.at(3), {0.5f, 0.5f}, 0.7f);
    ASSERT_TRUE(c);
    EXPECT_NEAR(c->film.x, 40, 1e-3f);
    EXPECT_NEAR(c->film.y, 20, 1e-3f);
}

// We / pdf = 1 / (A cos^3(theta) d^2): at the centre of a 90-degree square view (A = 4), a
// point 2 away gives 1/16; the lens's area cancels.
TEST(Camera, ConnectionImportanceIsOneOverAreaCosineCubedAndDistanceSquared) {
    CameraSpec spec;
    spec.from = {0, 0, 0}, spec.at = {0, 0, 1}, spec.fov = 90;
    const Camera pinhole(spec, 100, 100);
    EXPECT_NEAR(pinhole.connect({0, 0, 2}, {0.5f, 0.5f}, 0)->importance, 1 / 16.0f, 1e-6f);
    // 45 degrees off the axis, at distance sqrt(2): 1 / (4 (1/sqrt 2)^3 2) = 0.35355.
    EXPECT_NEAR(pinhole.connect({0, 1, 1}, {0.5f, 0.5f}, 0)->importance, 0.35355f, 1e-5f);
    spec.lens.radius = 0.1f;
    const Camera lens(spec, 100, 100);
    EXPECT_NEAR(lens.connect({0, 0, 2}, {0.5f, 0.5f}, 0)->importance, 1 / 16.0f, 1e-6f);
    spec.projection = Projection::orthographic;
    EXPECT_FALSE(Camera(spec, 100, 100).connect({0, 0, 2}, {0.5f, 0.5f}, 0));
}

}  // namespace
}  // namespace glint
