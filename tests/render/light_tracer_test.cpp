// The light integrator (particles from the lights, joined to the eye) against what is known: the
// furnace's exact answer, the path tracer's images of diffuse scenes, the particles counted, the
// image independent of threads, and the scenes it refuses.
#include "glint/render/integrators/light_tracer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <utility>

#include "glint/render/explain/explain.h"
#include "glint/render/render.h"
#include "glint/scene/integrator_fit.h"
#include "glint/scene/settings_problem.h"
#include "global_illumination_scenes.h"

namespace glint {
namespace {

using testing::directly_lit;
using testing::furnace;
using testing::red_wall;

TEST(LightTracing, AFurnaceOfEmittingWallsGivesLeOverOneMinusAlbedo) {
    const Color le{0.2f, 0.1f, 0.05f};
    const RenderResult r = render(World(furnace(0.5f, le, IntegratorKind::light)), {});
    testing::expect_furnace_answer(r.image, le / 0.5f);
    // One particle a sample. The eye sees a quarter of the furnace's wall: the particles that
    // reach some point of that quarter before Russian roulette ends them are seen.
    EXPECT_EQ(r.rays.particles,
              std::uint64_t(r.image.pixels.size()) * 256u / (testing::kUnderSanitizer ? 4u : 1u));
    EXPECT_GT(r.rays.particles_seen, r.rays.particles / 10);
    EXPECT_LT(r.rays.particles_seen, r.rays.particles / 2);
    EXPECT_GT(r.rays[RayKind::particle], r.rays.particles);
}

// Over 4 x 4 blocks, the means of two renders of each integrator agree within 5 standard
// errors of their difference, each render's variance taken from two seeds.
void expect_same_image(const Scene& a_scene, const Scene& b_scene) {
    const auto renders = [](const Scene& scene) {
        const World world(scene);
        RenderOptions one, two;
        one.seed = 1;
        two.seed = 2;
        return std::pair{render(world, one).image, render(world, two).image};
    };
    const auto [a1, a2] = renders(a_scene);
    const auto [b1, b2] = renders(b_scene);
    int failures = 0;
    for (int by = 0; by + 4 <= a1.height; by += 4)
        for (int bx = 0; bx + 4 <= a1.width; bx += 4)
            for (int channel = 0; channel < 3; ++channel) {
                const auto v = [&](const Image& im, int x, int y) {
                    const Color c = im.at(x, y);
                    return double(channel == 0 ? c.r : channel == 1 ? c.g : c.b);
                };
                double a = 0, b = 0, variance = 0;
                for (int y = by; y < by + 4; ++y)
                    for (int x = bx; x < bx + 4; ++x) {
                        a += (v(a1, x, y) + v(a2, x, y)) / 2;
                        b += (v(b1, x, y) + v(b2, x, y)) / 2;
                        const double da = v(a1, x, y) - v(a2, x, y), db = v(b1, x, y) - v(b2, x, y);
                        variance += (da * da + db * db) / 4;
                    }
                const double error = std::sqrt(variance) / 16;
                if (std::abs(a - b) / 16 > 5 * error + 0.002) {
                    ++failures;
                    ADD_FAILURE() << "block (" << bx << ", " << by << ") channel " << channel
                                  << ": " << a / 16 << " against " << b / 16 << ", standard error "
                                  << error;
                }
            }
    EXPECT_EQ(failures, 0);
}

TEST(LightTracing, AgreesWithThePathTracerOnADiffuseScene) {
    // The red wall beside a white floor: the wall's light on the floor comes both ways.
    Scene light = red_wall(IntegratorKind::light), path = red_wall(IntegratorKind::path);
    light.settings.filter = path.settings.filter = FilterSpec{FilterKind::box, 0.5f};
    light.settings.samples_per_pixel *= 4;
    expect_same_image(light, path);
}

TEST(LightTracing, AgreesWithThePathTracerOnDirectLighting) {
    // A point light, a rectangle area light and an emitting disk: each emits particles.
    expect_same_image(directly_lit(IntegratorKind::light), directly_lit(IntegratorKind::path));
}

// A floor of two triangles whose vertex normals all lean 40 degrees towards +x: particles light
// it as the path tracer's eye rays find it lit only with the adjoint's correction for shading
// normals (Veach 1997, 5.3): without it, parts of the light tracer's image are a third or a
// quarter of the path tracer's.
TEST(LightTracing, AgreesWithThePathTracerOnASmoothShadedSurface) {
    const auto scene = [](IntegratorKind integrator) {
        Scene s = directly_lit(integrator);
        MeshData floor;
        floor.positions = {{-8, 0, -8}, {8, 0, -8}, {8, 0, 8}, {-8, 0, 8}};
        const Normal3 leaning(std::sin(0.7f), std::cos(0.7f), 0);
        floor.normals = {leaning, leaning, leaning, leaning};
        floor.triangles = {{0, 2, 1}, {0, 3, 2}};
        s.objects[0] = {TriangleMesh{build_mesh(std::move(floor)).mesh}, 0};
        return s;
    };
    expect_same_image(scene(IntegratorKind::light), scene(IntegratorKind::path));
}

TEST(LightTracing, TheImageDoesNotDependOnThreadsOrTiles) {
    const World world(red_wall(IntegratorKind::light));
    RenderOptions one, two;
    one.threads = 1;
    two.threads = 2;
    two.tile_size = 3;
    const RenderResult a = render(world, one), b = render(world, two);
    EXPECT_EQ(a.image.pixels, b.image.pixels);
    EXPECT_EQ(a.rays, b.rays);
}

// glint explain's report of the particles on a pixel adds up, with the eye ray's value, to the
// pixel of a render of one sample a pixel through the one-pixel box filter.
TEST(LightTracing, ExplainReportsTheParticlesThatLightAPixel) {
    Scene scene = directly_lit(IntegratorKind::light);
    scene.settings.samples_per_pixel = 1;
    const World world(scene);
    const Image image = render(world, {}).image;
    int lit = 0;
    for (int y = 0; y < scene.settings.height; y += 3)
        for (int x = 0; x < scene.settings.width; x += 5) {
            const RayTree tree = explain(world, {x, y, 0, 0});
            ASSERT_TRUE(tree.particles);
            const ParticleReport& r = *tree.particles;
            EXPECT_EQ(r.traced, 24u * 16u);
            EXPECT_GT(r.seen, 0u);
            EXPECT_LE(r.seen, r.traced);
            const Color pixel = image.at(x, y), sum = tree.sample_value + r.value;
            EXPECT_NEAR(sum.r, pixel.r, 1e-5f + 1e-5f * pixel.r);
            EXPECT_NEAR(sum.b, pixel.b, 1e-5f + 1e-5f * pixel.b);
            if (r.landed == 0) continue;
            ++lit;
            // The largest few, largest first, each within the pixel's filter, and none beyond the
            // pixel's whole.
            ASSERT_FALSE(r.largest.empty());
            EXPECT_LE(r.largest.size(), 5u);
            for (std::size_t i = 0; i < r.largest.size(); ++i) {
                const ParticleContribution& c = r.largest[i];
                EXPECT_GT(c.weight, 0);
                EXPECT_LE(c.value.r * c.weight, r.value.r * 1.0001f);
                EXPECT_TRUE(c.light == "point light 0" || c.light == "area light 1 (rectangle)" ||
                            c.light == "emitting object 1 (disk)")
                    << c.light;
                if (i > 0) {
                    const auto share = [](const ParticleContribution& p) {
                        return (p.value.r + p.value.g + p.value.b) * p.weight;
                    };
                    EXPECT_GE(share(r.largest[i - 1]), share(c));
                }
            }
        }
    EXPECT_GE(lit, 3);
}

TEST(LightTracing, ScenesItCannotRenderAreRefused) {
    Scene scene = red_wall(IntegratorKind::light);
    EXPECT_NO_THROW(check_integrator_fits(scene));
    Scene no_falloff = scene;
    no_falloff.lights[0] = PointLight{{0, 3, 0}, Color::gray(1), {1, 0, 0}};
    try {
        check_integrator_fits(no_falloff);
        FAIL();
    } catch (const SceneError& e) {
        EXPECT_EQ(e.message(),
                  "light 0 (point) does not fall off as 1 / d^2 (attenuation constant 1, linear "
                  "0, quadratic 0): it has no finite power for the light integrator's particles "
                  "to carry");
    }
    Scene orthographic = scene;
    orthographic.camera.projection = Projection::orthographic;
    EXPECT_THROW(check_integrator_fits(orthographic), SceneError);
    // The path tracer takes both.
    no_falloff.settings.integrator = orthographic.settings.integrator = IntegratorKind::path;
    EXPECT_NO_THROW(check_integrator_fits(no_falloff));
    EXPECT_NO_THROW(check_integrator_fits(orthographic));
    scene.settings.adaptive = AdaptiveSampling{};
    scene.settings.samples_per_pixel = 64;
    const auto problem = settings_problem(scene.settings);
    ASSERT_TRUE(problem);
    EXPECT_EQ(problem->message, "adaptive sampling does not apply to the light integrator");
}

}  // namespace
}  // namespace glint
