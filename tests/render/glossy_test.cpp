// Glossy reflection and translucency: the lobe's exponent by worked numbers, its directions on
// the right side of the surface, and the mean a rough mirror and frosted glass converge to
// against the lobe's closed form.
#include <gtest/gtest.h>

#include <cmath>

#include "glint/render/integrators/distributed.h"
#include "glint/render/integrators/glossy_lobe.h"
#include "glint/render/integrators/whitted.h"
#include "glint/sampling/random.h"

namespace glint {
namespace {

TEST(GlossyLobe, ExponentOfRoughness) {
    EXPECT_FLOAT_EQ(phong_exponent_of_roughness(1), 0);
    EXPECT_FLOAT_EQ(phong_exponent_of_roughness(0.5f), 6);
    EXPECT_NEAR(phong_exponent_of_roughness(0.1f), 198, 1e-3);
}

TEST(GlossyLobe, DirectionsStayOnTheirSideOfTheSurface) {
    const Vector3 ng{0, 1, 0};
    const Vector3 grazing = normalize(Vector3{1, 0.05f, 0});
    EXPECT_EQ(spread_over_lobe(grazing, 0, {0.3f, 0.7f}, ng, true), grazing);  // a mirror
    int kept = 0;
    for (int i = 0; i < 1000; ++i) {
        const Point2 u{random_float(i, 0, 0, 5), random_float(i, 0, 1, 5)};
        if (const Vector3 d = spread_over_lobe(grazing, 0.3f, u, ng, true);
            d != kBlockedByTheSurface) {
            EXPECT_GT(dot(d, ng), 0);
            EXPECT_NEAR(length(d), 1, 1e-5);
            ++kept;
        }
        if (const Vector3 d = spread_over_lobe(-grazing, 0.3f, u, ng, false);
            d != kBlockedByTheSurface) {
            EXPECT_LT(dot(d, ng), 0);
        }
    }
    // About half the lobe around a grazing direction tips through the surface.
    EXPECT_GT(kept, 300);
    EXPECT_LT(kept, 700);
}

// The lobe (n+1)/(2 pi) cos^n around the normal puts the fraction 1 - c^(n+1) of its rays
// within the cone cos(alpha) > c. A disk of radius 1 at distance 1 along the normal fills the
// cone c = 1 / sqrt 2; with roughness 0.5 (n = 6) it receives 1 - 2^(-3.5) = 0.91161.
constexpr double kLobeOnDisk = 0.911612;

double mean_of(const World& world, const Ray& ray, int n) {
    const Sampler sampler(SamplerKind::jittered, n, 11);
    DistributedIntegrator integrator(world);
    RayStats stats;
    double sum = 0;
    for (int s = 0; s < n; ++s) {
        SampleStream stream(sampler, 0, std::uint32_t(s));
        sum += integrator.trace(ray, 2, 1, stream, stats).r;
    }
    return sum / n;
}

// A surface y = 0 of the given material, and an emitting disk of radius 1 at y = disk_y.
Scene surface_and_disk(const Material& surface, float disk_y) {
    Scene scene;
    scene.settings.background = Color{};
    scene.settings.integrator = IntegratorKind::distributed;
    Material light;
    light.ka = light.kd = 0;
    light.emission = Color::gray(1);
    scene.materials = {surface, light};
    scene.objects.push_back({Plane{{0, 0, 0}, {0, 1, 0}}, 0});
    scene.objects.push_back({Disk{{0, disk_y, 0}, {0, 1, 0}, 1, 0}, 1, true, false});
    return scene;
}

const Ray kDown{{0, 0.5f, 0}, {0, -1, 0}};

TEST(Glossy, ARoughMirrorSpreadsItsReflectionOverTheLobe) {
    Material mirror;
    mirror.ka = mirror.kd = 0;
    mirror.reflect = 1;
    mirror.roughness = 0.5f;
    const World world(surface_and_disk(mirror, 1));
    EXPECT_NEAR(mean_of(world, kDown, 4096), kLobeOnDisk, 0.01);
    // Whitted's tracer reflects along the mirror direction only: the disk fills it.
    RayStats stats;
    EXPECT_EQ(WhittedIntegrator(world).trace(kDown, 2, 1, stats).r, 1);
}

TEST(Glossy, FrostedGlassSpreadsItsRefractionOverTheLobe) {
    Material frosted;
    frosted.ka = frosted.kd = 0;
    frosted.transmit = 1;
    frosted.transmit_roughness = 0.5f;
    const World world(surface_and_disk(frosted, -1));
    EXPECT_NEAR(mean_of(world, kDown, 4096), kLobeOnDisk, 0.01);
}

TEST(Glossy, ABroaderLobeSeesLessOfTheDisk) {
    Material mirror;
    mirror.ka = mirror.kd = 0;
    mirror.reflect = 1;
    mirror.roughness = 1;  // n = 0: the uniform hemisphere, 1 - 1 / sqrt 2 of it on the disk
    EXPECT_NEAR(mean_of(World(surface_and_disk(mirror, 1)), kDown, 4096), 1 - std::sqrt(0.5), 0.01);
}

}  // namespace
}  // namespace glint
