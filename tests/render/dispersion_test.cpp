// Dispersion: a prism's deviation per wavelength against Cauchy's formula, a white emitter seen
// through dispersive glass staying white, and the dispersion scene's slit spread into a
// spectrum with blue bent more than red.
#include <gtest/gtest.h>

#include <cmath>

#include "glint/math/constants.h"
#include "glint/render/integrators/distributed.h"
#include "glint/render/integrators/surface_context.h"
#include "glint/render/render.h"
#include "glint/scene/load_scene.h"

namespace glint {
namespace {

// Cauchy glass n = A + B / lambda^2 with lambda in micrometres.
constexpr float kA = 1.5f, kB = 0.02f;
float cauchy(float lambda_nm) {
    const float um = lambda_nm / 1000;
    return kA + kB / (um * um);
}

Material cauchy_glass() {
    Material glass;
    glass.ka = glass.kd = glass.ks = 0;
    glass.transmit = 1;
    glass.dispersion = {DispersionModel::cauchy, {kA, kB}};
    glass.ior = refractive_index(glass.dispersion, 1, kReferenceWavelength);
    return glass;
}

// A prism of apex angle 60 degrees, its apex edge along y through (1.1547, 0, 0): the faces
// meeting there have outward normals (0.5, 0, -0.866) and (0.5, 0, 0.866); the base is x =
// -0.5774.
Scene prism_scene() {
    Scene scene;
    scene.materials.push_back(cauchy_glass());
    const Point3 a0{1.1547f, -1, 0}, a1{1.1547f, 1, 0}, b0{-0.5774f, -1, -1}, b1{-0.5774f, 1, -1},
        c0{-0.5774f, -1, 1}, c1{-0.5774f, 1, 1};
    for (const auto& face :
         {std::vector<Point3>{a0, b0, b1, a1}, std::vector<Point3>{c0, a0, a1, c1},
          std::vector<Point3>{b0, c0, c1, b1}, std::vector<Point3>{a0, c0, b0},
          std::vector<Point3>{a1, b1, c1}})
        scene.objects.push_back({std::get<Polygon>(make_polygon(face)), 0});
    return scene;
}

// The direction a ray leaves the prism in, following the refracted branch at each surface as
// both integrators do.
Vector3 exit_direction(const World& world, Ray ray) {
    MediumStack media;
    for (int crossing = 0; crossing < 2; ++crossing) {
        const auto hit = world.intersect(ray, {0, kInfinity}, kVisibleToCameraRays);
        if (!hit) break;
        const SurfaceContext c = surface_context(world, ray, *hit);
        const Branches b = branches_at(c, ray.direction, media, ray.wavelength);
        if (b.kt == 0) break;
        ray = spawn_from(world, c, ray, b.refracted);
        media = media_beyond(c, b, media, ray.wavelength);
    }
    return ray.direction;
}

TEST(Dispersion, APrismDeviatesEachWavelengthAsCauchysFormulaSays) {
    // Entering face 1 at incidence i, a ray leaves face 2 deviated by
    // D = i + asin(n sin(A - asin(sin(i) / n))) - A, with A = 60 degrees and n = n(lambda).
    const World world(prism_scene());
    const float i = radians(50.0f), apex = radians(60.0f);
    // The inward normal of face 1 is (-0.5, 0, 0.866); turned by i towards +x, the ray comes in.
    const float n_angle = radians(-30.0f);
    const Vector3 d{std::sin(n_angle + i), 0, std::cos(n_angle + i)};
    const Point3 entry{0.2887f, 0, -0.5f};  // on face 1
    double previous = 0;
    for (const float lambda : {420.0f, 500.0f, 587.56f, 656.0f}) {
        Ray ray{entry - d * 3, d};
        ray.wavelength = lambda;
        const Vector3 out = exit_direction(world, ray);
        const double deviation = std::acos(std::clamp(double(dot(out, d)), -1.0, 1.0));
        const double n = cauchy(lambda);
        const double expected =
            i + std::asin(n * std::sin(apex - std::asin(std::sin(i) / n))) - apex;
        EXPECT_NEAR(deviation, expected, 1e-4) << lambda << " nm";
        // Shorter waves bend more.
        if (previous > 0) {
            EXPECT_LT(deviation, previous) << lambda << " nm";
        }
        previous = deviation;
    }
    // A ray that carries every wavelength refracts at the d line.
    Ray white{entry - d * 3, d};
    Ray d_line = white;
    d_line.wavelength = kReferenceWavelength;
    const Vector3 a = exit_direction(world, white), b = exit_direction(world, d_line);
    EXPECT_NEAR(dot(a, b), 1, 1e-6);
}

TEST(Dispersion, AWhiteEmitterSeenThroughDispersiveGlassStaysWhite) {
    // A slab of Cauchy glass with parallel faces before a white emitting wall: every wavelength
    // leaves parallel to where it came in and meets the wall, so the wavelengths' colours must
    // add up to white, (1, 1, 1).
    Scene scene;
    scene.settings.integrator = IntegratorKind::distributed;
    scene.settings.background = Color{};
    scene.materials.push_back(cauchy_glass());
    Material wall;
    wall.ka = wall.kd = 0;
    wall.emission = Color::gray(1);
    scene.materials.push_back(wall);
    scene.objects.push_back({Box{{-10, -10, 1}, {10, 10, 1.5f}}, 0});
    scene.objects.push_back({Plane{{0, 0, 5}, {0, 0, -1}}, 1, true, false});
    const World world(scene);
    const int n = 4096;
    const Sampler sampler(SamplerKind::jittered, n, 3);
    DistributedIntegrator integrator(world);
    RayStats stats;
    Color sum;
    const Ray ray{{0, 0, 0}, normalize(Vector3{0.3f, 0.2f, 1})};
    for (int s = 0; s < n; ++s) {
        SampleStream stream(sampler, 0, std::uint32_t(s));
        sum += integrator.trace(ray, 1, 1, stream, stats);
    }
    const Color mean = sum / float(n);
    EXPECT_NEAR(mean.r, 1, 0.01);
    EXPECT_NEAR(mean.g, 1, 0.01);
    EXPECT_NEAR(mean.b, 1, 0.01);
}

TEST(Dispersion, ThePrismSceneSpreadsTheSlitIntoASpectrum) {
    Scene scene = load_scene(std::string(GLINT_SOURCE_DIR) + "/scenes/features/dispersion.yaml");
    scene.settings.width = 240;
    scene.settings.height = 135;
    scene.settings.samples_per_pixel = 16;
    const Image image = render(World(scene), {}).image;
    // The centroids along x of the red and of the blue light seen through the prism (the left
    // two thirds of the image; the slit itself is seen directly on the right).
    double red = 0, red_x = 0, blue = 0, blue_x = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width * 2 / 3; ++x) {
            const Color c = image.at(x, y);
            red += std::max(0.0f, c.r - c.b), red_x += std::max(0.0f, c.r - c.b) * x;
            blue += std::max(0.0f, c.b - c.r), blue_x += std::max(0.0f, c.b - c.r) * x;
        }
    ASSERT_GT(red, 1);
    ASSERT_GT(blue, 1);
    // Blue is deviated more towards the prism's base, which the camera sees on the image's left.
    EXPECT_LT(blue_x / blue + 5, red_x / red);
}

}  // namespace
}  // namespace glint
