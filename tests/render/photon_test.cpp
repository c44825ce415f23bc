// Progressive photon mapping: the radius schedule's worked numbers, the photon map's gathering
// against brute force, the furnace's exact answer, the path tracer's image of a diffuse scene,
// a caustic, eye rays that follow both parts of glass, and an image independent of threads and
// tiles.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "glint/render/explain/explain.h"
#include "glint/render/integrators/photon_mapper.h"
#include "glint/render/render.h"
#include "glint/sampling/random.h"
#include "glint/scene/load_scene.h"
#include "global_illumination_scenes.h"

namespace glint {
namespace {

using testing::furnace;
using testing::red_wall;

TEST(PhotonMapping, TheRadiusShrinksAsKnausAndZwickerSchedule) {
    // r_{i+1}^2 = r_i^2 (i + alpha) / (i + 1), alpha 2/3: 1, sqrt(5/6) = 0.91287, and then
    // sqrt(5/6 * 8/9) = 0.86066.
    EXPECT_EQ(PhotonIntegrator::radius_of_pass(1, 2.0f / 3, 0), 1);
    EXPECT_NEAR(PhotonIntegrator::radius_of_pass(1, 2.0f / 3, 1), 0.91287f, 1e-5f);
    EXPECT_NEAR(PhotonIntegrator::radius_of_pass(1, 2.0f / 3, 2), 0.86066f, 1e-5f);
    // It keeps shrinking, as i^((alpha - 1) / 2): slowly enough that each pass adds photons.
    EXPECT_LT(PhotonIntegrator::radius_of_pass(2, 0.7f, 1000), 2 * 0.4f);
    EXPECT_GT(PhotonIntegrator::radius_of_pass(2, 0.7f, 1000), 2 * 0.2f);
}

TEST(PhotonMap, GathersExactlyThePhotonsWithinTheRadius) {
    std::vector<Photon> photons;
    for (std::uint64_t i = 0; i < 2000; ++i)
        photons.push_back({{random_float(i, 0, 0, 1) * 4 - 2, random_float(i, 0, 1, 1) * 4 - 2,
                            random_float(i, 0, 2, 1) * 4 - 2},
                           {0, 1, 0},
                           {0, 1, 0},
                           Color::gray(float(i))});
    const PhotonMap map(photons, 0.3f);
    for (std::uint64_t q = 0; q < 100; ++q) {
        const Point3 p{random_float(q, 1, 0, 2) * 5 - 2.5f, random_float(q, 1, 1, 2) * 5 - 2.5f,
                       random_float(q, 1, 2, 2) * 5 - 2.5f};
        std::vector<float> found, expected;
        map.for_each_near(p, [&](const Photon& photon) { found.push_back(photon.power.r); });
        for (const Photon& photon : photons)
            if (length_squared(photon.position - p) <= 0.3f * 0.3f)
                expected.push_back(photon.power.r);
        std::sort(found.begin(), found.end());
        std::sort(expected.begin(), expected.end());
        EXPECT_EQ(found, expected) << q;
    }
}

TEST(PhotonMapping, AFurnaceOfEmittingWallsGivesLeOverOneMinusAlbedo) {
    Scene scene = furnace(0.5f, Color{0.2f, 0.1f, 0.05f}, IntegratorKind::photon);
    scene.settings.samples_per_pixel = testing::kUnderSanitizer ? 8 : 32;
    scene.settings.photons.per_pass = testing::kUnderSanitizer ? 5000 : 20000;
    const RenderResult r = render(World(scene), {});
    // The density estimate's blur is nothing in a furnace, whose light is the same everywhere;
    // the photons' noise is shared by all pixels of a pass, so the mean is judged alone.
    Color mean;
    for (const Color& c : r.image.pixels) mean += c / float(r.image.pixels.size());
    EXPECT_NEAR(mean.r, 0.4f, 0.03f * 0.4f);
    EXPECT_NEAR(mean.g, 0.2f, 0.03f * 0.2f);
    EXPECT_NEAR(mean.b, 0.1f, 0.03f * 0.1f);
    EXPECT_EQ(r.rays.particles, std::uint64_t(scene.settings.photons.per_pass) *
                                    std::uint64_t(scene.settings.samples_per_pixel));
    EXPECT_GT(r.rays.photons_stored, r.rays.particles / 2);
}

// The floor's pixels, whose light the wall reflects, agree with the path tracer's within 5
// standard errors and 4% for the blur of the photons' radius. The photons' noise is shared by the
// pixels of a pass, so it is measured across renders of other seeds, each pixel's spread pooled
// over the row for a steady estimate.
TEST(PhotonMapping, AgreesWithThePathTracerOnADiffuseScene) {
    Scene photon = red_wall(IntegratorKind::photon), path = red_wall(IntegratorKind::path);
    photon.settings.filter = path.settings.filter = FilterSpec{FilterKind::box, 0.5f};
    photon.settings.photons.per_pass = testing::kUnderSanitizer ? 5000 : 20000;
    path.settings.samples_per_pixel *= 2;
    constexpr int kSeeds = 4;
    const auto row_of = [](const Scene& scene, std::uint64_t seed) {
        RenderOptions options;
        options.seed = seed;
        const Image image = render(World(scene), options).image;
        std::vector<Color> row;
        for (int x = 0; x < image.width; ++x) row.push_back(image.at(x, image.height - 1));
        return row;
    };
    std::vector<std::vector<Color>> photons, paths;
    for (int s = 0; s < kSeeds; ++s) {
        photons.push_back(row_of(photon, 1 + s));
        paths.push_back(row_of(path, 1 + s));
    }
    const int width = int(photons[0].size());
    for (int channel = 0; channel < 2; ++channel) {
        const auto of = [&](const Color& c) { return double(channel == 0 ? c.r : c.g); };
        std::vector<double> photon_mean(width), path_mean(width);
        double photon_variance = 0, path_variance = 0;  // one render's, pooled over the row
        for (int x = 0; x < width; ++x) {
            for (int s = 0; s < kSeeds; ++s) {
                photon_mean[x] += of(photons[s][x]) / kSeeds;
                path_mean[x] += of(paths[s][x]) / kSeeds;
            }
            for (int s = 0; s < kSeeds; ++s) {
                photon_variance += std::pow(of(photons[s][x]) - photon_mean[x], 2);
                path_variance += std::pow(of(paths[s][x]) - path_mean[x], 2);
            }
        }
        photon_variance /= width * (kSeeds - 1);
        path_variance /= width * (kSeeds - 1);
        const double error = std::sqrt((photon_variance + path_variance) / kSeeds);
        for (int x = 0; x < width; ++x)
            EXPECT_NEAR(photon_mean[x], path_mean[x], 5 * error + 0.04 * path_mean[x] + 0.002)
                << "pixel " << x << " channel " << channel << ", standard error " << error;
    }
}

// explain builds the photon map of the sample's pass, as the render did: its tree gives the
// rendered pixel to the last bit, the photon map's estimate among its terms.
TEST(PhotonMapping, ExplainGivesTheRenderedPixelToTheLastBit) {
    Scene scene = load_scene(std::string(GLINT_SOURCE_DIR) + "/scenes/features/caustics.yaml");
    scene.settings.width = 12;
    scene.settings.height = 8;
    scene.settings.samples_per_pixel = 2;
    scene.settings.photons.per_pass = 2000;
    scene.settings.filter = FilterSpec{FilterKind::box, 0.5f};
    const World world(scene);
    RenderOptions options;
    options.seed = 3;
    const Image image = render(world, options).image;
    int gathered = 0;
    for (int y = 0; y < scene.settings.height; ++y)
        for (int x = 0; x < scene.settings.width; ++x) {
            Color sum;
            for (int s = 0; s < 2; ++s) {
                const RayTree tree = explain(world, {x, y, s, options.seed});
                const Color e = evaluate(tree);
                ASSERT_EQ(e, tree.sample_value) << x << ", " << y << " sample " << s;
                sum += tree.sample_value;
                for (const RayNode& n : tree.nodes) gathered += n.path && n.path->photons > 0;
            }
            EXPECT_EQ(sum / 2.0f, image.at(x, y)) << x << ", " << y;
        }
    EXPECT_GT(gathered, 0);
}

// A pane that reflects kr and transmits kt (index 1, no Fresnel) facing the eye, an emitting
// disk of Le 2 behind the eye that it mirrors and one of Le 1 behind it: the eye rays follow
// both parts, so every sample is kr 2 + kt 1 exactly, where picking one part would give 2 or 1.
// A part carrying less than 5% of the sample goes on by Russian roulette: kr 0.02 is traced
// with probability 0.4 and then weighs 0.05, and the pixels' mean is still 0.02 2 + 0.98.
Scene mirroring_pane(float kr, float kt) {
    Scene scene;
    scene.settings.width = 6;
    scene.settings.height = 4;
    scene.settings.integrator = IntegratorKind::photon;
    scene.settings.samples_per_pixel = 64;
    scene.settings.photons.per_pass = 100;
    scene.camera.from = {0, 0, -1};
    scene.camera.at = {0, 0, 0};
    scene.camera.fov = 20;
    Material pane, mirrored, behind;
    pane.ka = pane.kd = 0;
    pane.reflect = kr;
    pane.transmit = kt;
    mirrored.ka = mirrored.kd = behind.ka = behind.kd = 0;
    mirrored.emission = Color::gray(2);
    behind.emission = Color::gray(1);
    scene.materials = {pane, mirrored, behind};
    scene.objects.push_back({Plane{{0, 0, 0}, {0, 0, -1}}, 0});
    scene.objects.push_back({Disk{{0, 0, -5}, {0, 0, 1}, 100}, 1});
    scene.objects.push_back({Disk{{0, 0, 5}, {0, 0, -1}, 100}, 2});
    return scene;
}

TEST(PhotonMapping, EyeRaysFollowBothPartsOfGlassAndRouletteOnlyTheLightOnes) {
    const Image both = render(World(mirroring_pane(0.3f, 0.7f)), RenderOptions{}).image;
    for (const Color& c : both.pixels) EXPECT_NEAR(c.r, 0.3f * 2 + 0.7f, 1e-5f);

    const World light(mirroring_pane(0.02f, 0.98f));
    const Image image = render(light, RenderOptions{}).image;
    double mean = 0;
    for (const Color& c : image.pixels) mean += c.r / double(image.pixels.size());
    // Each sample is 0.98 + 0.1 with probability 0.4: its standard deviation is 0.049, and
    // 24 x 64 samples make the mean's 0.00125.
    EXPECT_NEAR(mean, 0.02 * 2 + 0.98, 5 * 0.00125);
    // explain tells it: the reflected branch has k 0.02 and survival 0.4, traced with its
    // colour times 0.05 or ended by Russian roulette.
    int traced = 0;
    for (int s = 0; s < 64; ++s) {
        const RayTree tree = explain(light, {2, 2, s, 0});
        ASSERT_EQ(tree.nodes[0].branches.size(), 2u);
        const BranchRecord& mirror = tree.nodes[0].branches[0];
        EXPECT_EQ(mirror.kind, RayKind::reflected);
        EXPECT_NEAR(mirror.k, 0.02f, 1e-7f);
        EXPECT_NEAR(mirror.survival, 0.4f, 1e-6f);
        if (mirror.child >= 0) {
            ++traced;
            EXPECT_NEAR(mirror.factor.r, 0.05f, 1e-6f);
        } else {
            EXPECT_EQ(mirror.stop, StopReason::roulette);
        }
        EXPECT_EQ(tree.nodes[0].branches[1].survival, 1);
        EXPECT_GE(tree.nodes[0].branches[1].child, 0);
    }
    // 64 draws of probability 0.4: 25.6 on average, standard deviation 3.9.
    EXPECT_GT(traced, 10);
    EXPECT_LT(traced, 42);
}

TEST(PhotonMapping, TheImageDoesNotDependOnThreadsOrTiles) {
    Scene scene = red_wall(IntegratorKind::photon);
    scene.settings.samples_per_pixel = 4;
    scene.settings.photons.per_pass = 3000;
    const World world(scene);
    RenderOptions one, two;
    one.threads = 1;
    two.threads = 2;
    two.tile_size = 3;
    const RenderResult a = render(world, one), b = render(world, two);
    EXPECT_EQ(a.image.pixels, b.image.pixels);
    EXPECT_EQ(a.rays, b.rays);
}

}  // namespace
}  // namespace glint
