// Depth of field and motion blur in rendered images: a small glowing sphere at the focus
// distance stays sharp and one beyond it blurs into the thin lens' circle of confusion; a
// moving one draws a streak as long as its path on the film. Measured by the second moments of
// the image's brightness, which for a uniform disk of radius rho is rho^2 / 2 and for a uniform
// streak of length L is L^2 / 12.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <variant>
#include <vector>

#include "glint/math/constants.h"
#include "glint/render/render.h"
#include "glint/scene/load_scene.h"

namespace glint {
namespace {

constexpr int kSize = 64;
constexpr float kFov = 30;
// Pixels per scene unit at depth z: kSize / 2 over the half window tan(15 deg) z.
float pixels_per_unit(float z) { return kSize / 2 / (std::tan(radians(kFov / 2)) * z); }

// A black scene with one glowing sphere of radius 0.02 (or as given), seen by a camera at the
// origin looking down +z; box-filtered, many jittered samples.
Scene glowing_sphere(Point3 center, float radius = 0.02f) {
    Scene scene;
    scene.settings.width = scene.settings.height = kSize;
    scene.settings.integrator = IntegratorKind::distributed;
    scene.settings.samples_per_pixel = 256;
    scene.settings.filter = FilterSpec{FilterKind::box, 0.5f};
    scene.settings.background = Color{};
    scene.camera.from = {0, 0, 0};
    scene.camera.at = {0, 0, 1};
    scene.camera.fov = kFov;
    Material glow;
    glow.ka = glow.kd = 0;
    glow.emission = Color::gray(1);
    scene.materials.push_back(glow);
    scene.objects.push_back({Sphere{center, radius}, 0, true, false});
    return scene;
}

struct Moments {
    double total = 0;             // the summed brightness
    double var_x = 0, var_y = 0;  // its variance along each axis, in pixels^2
};

Moments moments_of(const Image& image) {
    Moments m;
    double sx = 0, sy = 0, sxx = 0, syy = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const double w = image.at(x, y).r, px = x + 0.5, py = y + 0.5;
            m.total += w;
            sx += w * px, sy += w * py, sxx += w * px * px, syy += w * py * py;
        }
    m.var_x = sxx / m.total - (sx / m.total) * (sx / m.total);
    m.var_y = syy / m.total - (sy / m.total) * (sy / m.total);
    return m;
}

Moments render_moments(const Scene& scene) {
    const RenderResult result = render(World(scene), {});
    return moments_of(result.image);
}

// A pixel-wide box filter adds the variance of a uniform pixel, 1/12, along each axis.
constexpr double kPixelVariance = 1.0 / 12;

TEST(DepthOfField, APointAtTheFocusDistanceStaysSharp) {
    Scene scene = glowing_sphere({0.05f, 0.03f, 4});
    scene.camera.lens.radius = 0.3f;
    scene.camera.lens.focus_distance = 4;
    const Moments m = render_moments(scene);
    EXPECT_LT(m.var_x + m.var_y, 0.5);
}

// The light of a sphere of radius r at depth z on the film: its disk's area in pixels.
double disk_area(float r, float z) {
    const double rho = r * pixels_per_unit(z);
    return kPi * rho * rho;
}

TEST(DepthOfField, APointOffFocusBlursToTheCircleOfConfusion) {
    // At depth 8 with focus at 4 the circle of confusion has radius r |8 - 4| / 4 = r in the
    // scene: 0.3 units, 4.48 pixels.
    Scene scene = glowing_sphere({0.05f, 0.03f, 8}, 0.1f);
    scene.camera.lens.radius = 0.3f;
    scene.camera.lens.focus_distance = 4;
    const double rho = 0.3 * pixels_per_unit(8);
    const Moments blurred = render_moments(scene);
    // The disk's variance per axis is rho^2 / 4, the sphere's own disk adds its own.
    const double sphere = 0.1 * pixels_per_unit(8);
    const double expected = (rho * rho + sphere * sphere) / 4 + kPixelVariance;
    EXPECT_NEAR(blurred.var_x, expected, 0.03 * expected);
    EXPECT_NEAR(blurred.var_y, expected, 0.03 * expected);
    // Blurring spreads the light; it does not lose or make any.
    EXPECT_NEAR(blurred.total, disk_area(0.1f, 8), 0.03 * blurred.total);
}

// How hexagonal the image's light is, and which way: the mean of cos(6 theta) about its centroid,
// weighted by brightness times r^2. A disk gives 0; a uniform regular hexagon with a vertex
// along x gives 0.1187 (a vertex along y, -0.1187), as integrating it over the hexagon gives;
// sums over every pixel keep the noise of a sparsely hit blur small.
double hexagonality(const Image& image) {
    const Moments m = moments_of(image);
    double cx = 0, cy = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            cx += image.at(x, y).r * (x + 0.5), cy += image.at(x, y).r * (y + 0.5);
        }
    cx /= m.total, cy /= m.total;
    double sum = 0, weights = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const double dx = x + 0.5 - cx, dy = y + 0.5 - cy, w = image.at(x, y).r;
            sum += w * (dx * dx + dy * dy) * std::cos(6 * std::atan2(dy, dx));
            weights += w * (dx * dx + dy * dy);
        }
    return sum / weights;
}

TEST(DepthOfField, ABladedApertureBlursAPointIntoItsPolygon) {
    // At depth 40 with focus at 4, an aperture of radius 0.5 blurs a point into a disk of
    // radius 0.5 * 36 / 4 = 4.5 units, 13 pixels, which the sphere's own disk (0.6 units)
    // rounds a little. Six blades make it a hexagon with a vertex to the right; turned by 30
    // degrees, a vertex points up.
    Scene scene = glowing_sphere({0, 0, 40}, 0.6f);
    scene.camera.lens.radius = 0.5f;
    scene.camera.lens.focus_distance = 4;
    EXPECT_NEAR(hexagonality(render(World(scene), {}).image), 0, 0.02);
    scene.camera.lens.blades = 6;
    EXPECT_NEAR(hexagonality(render(World(scene), {}).image), 0.1187, 0.025);
    scene.camera.lens.blade_rotation = 30;
    EXPECT_NEAR(hexagonality(render(World(scene), {}).image), -0.1187, 0.025);
}

// scenes/features/depth-of-field.yaml says its far lamps become hexagons: they do when each
// lamp is small beside its circle of confusion, which it then takes the shape of.
TEST(DepthOfField, TheFeatureScenesLampsAreSmallBesideTheirBlur) {
    const Scene scene =
        load_scene(std::string(GLINT_SOURCE_DIR) + "/scenes/features/depth-of-field.yaml");
    const CameraSpec& c = scene.camera;
    EXPECT_EQ(c.lens.blades, 6);
    const Vector3 view = normalize(c.at - c.from);
    int lamps = 0;
    for (const SceneObject& object : scene.objects) {
        if (scene.materials[object.material].name != "lamp") continue;
        const Sphere& lamp = std::get<Sphere>(object.shape);
        const float depth = dot(lamp.center - c.from, view);
        // The circle of confusion's radius at the lamp's depth, in the scene.
        const float blur = c.lens.radius * (depth - c.lens.focus_distance) / c.lens.focus_distance;
        EXPECT_LT(lamp.radius, 0.35f * blur) << "a lamp at depth " << depth;
        ++lamps;
    }
    EXPECT_EQ(lamps, 3);
}

TEST(MotionBlur, AMovingSphereDrawsAStreakAsLongAsItsPath) {
    // The sphere slides from x = -0.5 to 0.5 at depth 4 while the shutter is open: a streak of
    // L = 1 unit, 29.9 pixels, along x, and none along y.
    Scene scene = glowing_sphere({0, 0, 4}, 0.05f);
    scene.camera.shutter_open = 0, scene.camera.shutter_close = 1;
    const auto motion = std::make_shared<const AnimatedTransform>(std::vector<Keyframe>{
        {0, Transform::translate({-0.5f, 0, 0})}, {1, Transform::translate({0.5f, 0, 0})}});
    scene.objects[0].shape = Moving{motion, std::make_shared<const Shape>(scene.objects[0].shape)};
    const Moments streak = render_moments(scene);
    const double length = pixels_per_unit(4), radius = 0.05 * pixels_per_unit(4);
    const double along = length * length / 12 + radius * radius / 4 + kPixelVariance;
    const double across = radius * radius / 4 + kPixelVariance;
    EXPECT_NEAR(streak.var_x, along, 0.03 * along);
    EXPECT_NEAR(streak.var_y, across, 0.1 * across);
    // The light of the sphere standing still, spread along its path.
    EXPECT_NEAR(streak.total, disk_area(0.05f, 4), 0.03 * streak.total);
}

}  // namespace
}  // namespace glint
