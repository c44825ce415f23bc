// glint explain: the recorded ray tree gives back the rendered sample to the last bit, for every
// pixel of scenes of both integrators; the notes' worked ray-sphere example appears in it with
// its numbers; each reason a branch stops is recorded; the formats carry the numbers.
#include "glint/render/explain/explain.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

#include "glint/math/constants.h"
#include "glint/render/explain/ray_tree_formats.h"
#include "glint/render/render.h"
#include "glint/scene/load_scene.h"
#include "recorder_test_scenes.h"

namespace glint {
namespace {

bool same_bits(Color a, Color b) { return std::memcmp(&a, &b, sizeof a) == 0; }

std::string text_of(Color c) {
    char s[96];
    std::snprintf(s, sizeof s, "(%.9g, %.9g, %.9g)", double(c.r), double(c.g), double(c.b));
    return s;
}

Scene small(const std::string& file, int spp) {
    Scene scene = load_scene(std::string(GLINT_SOURCE_DIR) + "/" + file);
    scene.settings.width = 24;
    scene.settings.height = 18;
    scene.settings.samples_per_pixel = spp;
    if (!is_valid_sample_count(sampler_of(scene.settings), spp))
        scene.settings.sampler = SamplerKind::jittered;
    scene.settings.filter = FilterSpec{FilterKind::box, 0.5f};  // a pixel is its samples' mean
    return scene;
}

// Every node's colour is its terms and its children's colours combined as the integrator
// combines them.
void expect_every_node_evaluates_to_its_value(const RayTree& tree) {
    for (std::size_t i = 0; i < tree.nodes.size(); ++i)
        ASSERT_TRUE(same_bits(evaluate(tree, int(i)), tree.nodes[i].value))
            << "node " << i << ": " << text_of(evaluate(tree, int(i))) << " recorded "
            << text_of(tree.nodes[i].value);
}

class ExplainScenes : public ::testing::TestWithParam<const char*> {};

TEST_P(ExplainScenes, TreeGivesTheRenderedPixelToTheLastBit) {
    for (const int spp : {1, 4}) {
        const Scene scene = small(GetParam(), spp);
        const World world(scene);
        RenderOptions options;
        options.seed = 5;
        options.threads = 1;
        const Image image = render(world, options).image;
        std::size_t recorded = 0;  // light samples and secondary rays
        for (int y = 0; y < scene.settings.height; ++y)
            for (int x = 0; x < scene.settings.width; ++x) {
                // The one-pixel box film: the samples added in order, over their count.
                Color sum;
                for (int s = 0; s < spp; ++s) {
                    const RayTree tree = explain(world, {x, y, s, options.seed});
                    ASSERT_TRUE(same_bits(evaluate(tree), tree.sample_value))
                        << GetParam() << " pixel " << x << "," << y << " sample " << s;
                    expect_every_node_evaluates_to_its_value(tree);
                    sum += tree.sample_value;
                    recorded += tree.nodes.size() - 1;
                    for (const RayNode& n : tree.nodes)
                        for (const LightRecord& light : n.lights) recorded += light.samples.size();
                }
                const Color pixel = image.pixels[std::size_t(y) * scene.settings.width + x];
                ASSERT_TRUE(same_bits(sum / float(spp), pixel))
                    << GetParam() << " pixel " << x << "," << y << ": the tree gives "
                    << text_of(sum / float(spp)) << ", the render " << text_of(pixel);
            }
        EXPECT_GT(recorded, 0u);
    }
}

INSTANTIATE_TEST_SUITE_P(Scenes, ExplainScenes, ::testing::ValuesIn(testing::kRecorderTestScenes),
                         testing::scene_test_name);

// Under adaptive sampling each sample counts for its own pixel alone, with the filter's weight
// that explain shows: the pixel is its samples' weighted mean, to the last bit.
TEST(Explain, AnAdaptivePixelIsTheWeightedMeanOfItsOwnSamples) {
    Scene scene = load_scene(std::string(GLINT_SOURCE_DIR) + "/scenes/features/adaptive.yaml");
    scene.settings.width = 16;
    scene.settings.height = 9;
    scene.settings.samples_per_pixel = 32;
    scene.settings.adaptive->min_samples = 4;
    for (const FilterSpec filter :
         {FilterSpec{FilterKind::gaussian, 1.5f}, FilterSpec{FilterKind::mitchell, 2}}) {
        scene.settings.filter = filter;
        const World world(scene);
        RenderOptions options;
        options.seed = 2;
        options.record_samples_taken = true;
        const RenderResult result = render(world, options);
        int negative = 0;
        for (int y = 0; y < scene.settings.height; ++y)
            for (int x = 0; x < scene.settings.width; ++x) {
                const int taken = int(result.samples_taken.at(x, y).r);
                Color sum;
                float weights = 0;
                for (int s = 0; s < taken; ++s) {
                    const RayTree tree = explain(world, {x, y, s, options.seed});
                    ASSERT_TRUE(tree.filter_weight);
                    // Drawn around the pixel's centre, within the filter's radius.
                    EXPECT_LE(std::abs(tree.film.x - (x + 0.5f)), filter.radius);
                    EXPECT_LE(std::abs(tree.film.y - (y + 0.5f)), filter.radius);
                    sum += tree.sample_value * *tree.filter_weight;
                    weights += *tree.filter_weight;
                    negative += *tree.filter_weight < 0;
                }
                ASSERT_TRUE(same_bits(sum / weights, result.image.at(x, y)))
                    << "pixel " << x << "," << y << ": the trees give " << text_of(sum / weights)
                    << ", the render " << text_of(result.image.at(x, y));
            }
        // Mitchell's negative lobes weigh some samples negatively.
        if (filter.kind == FilterKind::mitchell) {
            EXPECT_GT(negative, 0);
        }
        const RayTree tree = explain(world, {3, 4, 1, options.seed});
        EXPECT_NE(ray_tree_text(tree).find("counting for this pixel alone with the filter's "
                                           "weight"),
                  std::string::npos);
        EXPECT_NE(ray_tree_json(tree).find("\"filter_weight\": "), std::string::npos);
    }
}

// The notes' "Strahl-Kugel Schnitt, Beispiel": P0 = (1 -2 -1), R || (1 2 4), M = (3 0 5),
// r = 3 gives t1 = 3.744, S1 = (1.816 -0.368 2.269), N1 = (-0.395 -0.123 -0.910). The eye ray of
// a one-pixel image through its centre is that ray.
TEST(Explain, TheNotesWorkedRaySphereExampleAppearsInTheTree) {
    Scene scene;
    scene.settings.width = scene.settings.height = 1;
    scene.camera.from = {1, -2, -1};
    scene.camera.at = {2, 0, 3};
    scene.camera.up = {0, 0, 1};
    scene.materials.push_back(Material{});
    scene.materials.back().name = "chalk";
    scene.objects.push_back({Sphere{{3, 0, 5}, 3}, 0});
    scene.lights.push_back(PointLight{{1, -2, -1}, Color::gray(1)});
    const World world(scene);
    const RayTree tree = explain(world, {0, 0, 0, 0});
    ASSERT_FALSE(tree.nodes.empty());
    const RayNode& eye = tree.nodes[0];
    EXPECT_NEAR(eye.ray.direction.x * std::sqrt(21.0f), 1, 1e-5);
    EXPECT_NEAR(eye.ray.direction.y * std::sqrt(21.0f), 2, 1e-5);
    EXPECT_NEAR(eye.ray.direction.z * std::sqrt(21.0f), 4, 1e-5);
    EXPECT_NEAR(eye.t, 3.744, 2e-3);
    EXPECT_NEAR(eye.point.x, 1.816, 2e-3);
    EXPECT_NEAR(eye.point.y, -0.368, 2e-3);
    EXPECT_NEAR(eye.point.z, 2.269, 2e-3);
    EXPECT_NEAR(eye.geometric_normal.x, -0.395, 2e-3);
    EXPECT_NEAR(eye.geometric_normal.y, -0.123, 2e-3);
    EXPECT_NEAR(eye.geometric_normal.z, -0.910, 2e-3);
    EXPECT_TRUE(eye.entering);
    EXPECT_EQ(eye.material, "chalk");
    EXPECT_EQ(eye.shape, "sphere");
    // The light sits at the eye: N.L is the cosine between the ray and the normal, h / ... .
    ASSERT_EQ(eye.lights.size(), 1u);
    const LightSampleRecord& light = eye.lights[0].samples[0];
    EXPECT_NEAR(light.n_dot_l, -dot(eye.ray.direction, eye.geometric_normal), 1e-5);
    EXPECT_EQ(light.shadow, (Color{1, 1, 1}));
    const std::string text = ray_tree_text(tree);
    // Unrounded: h = 30 / sqrt(21) = 6.5465, s = sqrt(9 - 44 + h^2) = 2.8031, t = 3.7434.
    EXPECT_NE(text.find("at t = 3.743"), std::string::npos) << text;
    EXPECT_NE(text.find("point (1.817, -0.3662, 2.268), normal (-0.3944, -0.1221, -0.9108)"),
              std::string::npos)
        << text;
}

// The camera inside a diamond sphere, off its centre, looking along it: the eye ray meets the
// inside at 64 degrees, beyond the critical angle of 24.6, and so does every reflection after.
Scene inside_a_diamond(int max_depth, float min_weight) {
    Scene scene;
    scene.settings.width = scene.settings.height = 1;
    scene.settings.max_depth = max_depth;
    scene.settings.min_weight = min_weight;
    scene.camera.from = {0.9f, 0, 0};
    scene.camera.at = {0.9f, 0, 1};
    Material diamond;
    diamond.name = "diamond";
    diamond.reflect = 0.02f;
    diamond.transmit = 0.9f;
    diamond.ior = 2.4f;
    scene.materials.push_back(diamond);
    scene.objects.push_back({Sphere{{0, 0, 0}, 1}, 0});
    return scene;
}

TEST(Explain, EachReasonARayOrBranchStopsIsRecorded) {
    // Total internal reflection: the transmitted weight goes to the reflected ray, 0.92.
    RayTree tree = explain(World(inside_a_diamond(2, 0.01f)), {0, 0, 0, 0});
    expect_every_node_evaluates_to_its_value(tree);
    ASSERT_EQ(tree.nodes.size(), 2u);
    const RayNode& eye = tree.nodes[0];
    EXPECT_FALSE(eye.entering);
    EXPECT_TRUE(eye.total_internal_reflection);
    EXPECT_FLOAT_EQ(eye.n1, 2.4f);
    EXPECT_FLOAT_EQ(eye.n2, 1);
    EXPECT_NEAR(eye.cos_incident, std::sqrt(1 - 0.81f), 1e-5);
    ASSERT_EQ(eye.branches.size(), 2u);
    EXPECT_EQ(eye.branches[0].kind, RayKind::reflected);
    EXPECT_FLOAT_EQ(eye.branches[0].k, 0.92f);
    EXPECT_EQ(eye.branches[0].child, 1);
    EXPECT_EQ(eye.branches[1].stop, StopReason::total_internal_reflection);
    EXPECT_EQ(tree.nodes[1].stop, StopReason::max_depth);
    std::string text = ray_tree_text(tree);
    EXPECT_NE(text.find("total internal reflection"), std::string::npos) << text;
    EXPECT_NE(text.find("stops: the maximum depth (2)"), std::string::npos) << text;

    // The second reflection's weight, 0.92^2 = 0.846, is below a minimum of 0.9.
    tree = explain(World(inside_a_diamond(8, 0.9f)), {0, 0, 0, 0});
    ASSERT_EQ(tree.nodes.size(), 2u);
    EXPECT_EQ(tree.nodes[1].branches.at(0).stop, StopReason::min_weight);
    text = ray_tree_text(tree);
    EXPECT_NE(text.find("not traced: weight 0.8464 is below the minimum weight"), std::string::npos)
        << text;

    // Looking away from everything.
    Scene empty = inside_a_diamond(2, 0.01f);
    empty.objects.clear();
    tree = explain(World(empty), {0, 0, 0, 0});
    ASSERT_EQ(tree.nodes.size(), 1u);
    EXPECT_EQ(tree.nodes[0].stop, StopReason::missed);
    EXPECT_TRUE(same_bits(evaluate(tree), empty.settings.background));
}

// Snell's law at the first surface with worked numbers: entering glass of index 1.5 at 30
// degrees, sin(t) = sin(30) / 1.5 = 1/3, t = 19.47 degrees.
TEST(Explain, SnellsLawValuesAtASurface) {
    Scene scene;
    scene.settings.width = scene.settings.height = 1;
    const float s = std::sin(radians(30.0f)), c = std::cos(radians(30.0f));
    scene.camera.from = {-5 * s, 0, -5 * c};
    scene.camera.at = {0, 0, 0};
    Material glass;
    glass.transmit = 0.9f;
    glass.ior = 1.5f;
    scene.materials.push_back(glass);
    scene.objects.push_back({Plane{{0, 0, 0}, Normal3{0, 0, -1}}, 0});
    const World world(scene);
    const RayTree tree = explain(world, {0, 0, 0, 0});
    const RayNode& eye = tree.nodes.at(0);
    ASSERT_TRUE(eye.transmits);
    EXPECT_FLOAT_EQ(eye.n1, 1);
    EXPECT_FLOAT_EQ(eye.n2, 1.5f);
    EXPECT_NEAR(eye.cos_incident, c, 1e-5);
    EXPECT_NEAR(eye.cos_refracted, std::sqrt(1 - 1.0f / 9), 1e-5);
    ASSERT_EQ(eye.branches.size(), 1u);
    EXPECT_EQ(eye.branches[0].kind, RayKind::refracted);
    EXPECT_EQ(eye.branches[0].k, 0.9f);
}

// Every hit tells how wide the ray's pencil is there: a pixel's step of the window at the
// distance of the wall, and wider again after a convex mirror.
TEST(Explain, EachHitTellsHowWideItsPencilIs) {
    Scene scene;
    scene.settings.width = scene.settings.height = 100;
    scene.settings.filter = FilterSpec{FilterKind::box, 0.5f};
    scene.camera.from = {0, 0, 0};
    scene.camera.at = {0, 0, 1};
    scene.camera.fov = 90;  // the window at distance 1 is 2 across: 0.02 a pixel
    Material mirror;
    mirror.reflect = 1;
    scene.materials = {Material{}, mirror};
    scene.objects.push_back({Plane{{0, 0, 5}, Normal3{0, 0, -1}}, 0});
    scene.objects.push_back({Plane{{0, 0, -5}, Normal3{0, 0, 1}}, 0});  // behind the camera
    scene.objects.push_back({Sphere{{0, 0, 2}, 0.5f}, 1});
    const World world(scene);
    // Beside the ball, at the wall 5 away: 5 x 0.02 a pixel (a little more off the centre).
    const RayTree wall = explain(world, {10, 50, 0, 0});
    ASSERT_TRUE(wall.nodes.at(0).pencil);
    EXPECT_NEAR(pencil_width(*wall.nodes[0].pencil), 0.1f, 0.01f);
    EXPECT_NE(ray_tree_text(wall).find("pencil 0.1"), std::string::npos) << ray_tree_text(wall);
    EXPECT_NE(ray_tree_json(wall).find("\"pencil\": {\"width\": "), std::string::npos);
    // Off the ball's mirror, back past the camera to the wall behind it: the convex mirror
    // spreads the pencil many times wider than it met the ball.
    const RayTree ball = explain(world, {53, 52, 0, 0});
    ASSERT_GE(ball.nodes.size(), 2u);
    const RayNode& reflected = ball.nodes[1];
    EXPECT_EQ(reflected.kind, RayKind::reflected);
    EXPECT_EQ(reflected.object, 1u);
    ASSERT_TRUE(ball.nodes[0].pencil && reflected.pencil);
    EXPECT_GT(pencil_width(*reflected.pencil), 10 * pencil_width(*ball.nodes[0].pencil));
}

// A hit on a mesh names its triangle, in the tree and in the text.
TEST(Explain, AMeshHitNamesItsTriangle) {
    const Scene scene = small("scenes/features/meshes.yaml", 1);
    const World world(scene);
    int meshes = 0;
    for (int y = 0; y < scene.settings.height; ++y)
        for (int x = 0; x < scene.settings.width; ++x) {
            const RayTree tree = explain(world, {x, y, 0, 0});
            const RayNode& eye = tree.nodes[0];
            // The floor is a plane; every other object is a mesh, placed by a transform.
            EXPECT_EQ(eye.triangle.has_value(), eye.stop != StopReason::missed && eye.object > 0);
            if (!eye.triangle) continue;
            ++meshes;
            const std::string text = ray_tree_text(tree);
            EXPECT_NE(text.find("(transformed, triangle " + std::to_string(*eye.triangle) + ")"),
                      std::string::npos)
                << text;
        }
    EXPECT_GT(meshes, 0);
}

// JSON writes every float with 9 significant digits, so the sample read back is the same float.
TEST(Explain, JsonCarriesTheSampleExactlyAndDotIsAGraph) {
    const Scene scene = small("scenes/distributed-showcase.yaml", 4);
    const World world(scene);
    const RayTree tree = explain(world, {12, 10, 3, 9});
    const std::string json = ray_tree_json(tree);
    const std::size_t at = json.find("\"sample_value\": [");
    ASSERT_NE(at, std::string::npos) << json;
    Color read;
    ASSERT_EQ(
        std::sscanf(json.c_str() + at, "\"sample_value\": [%f, %f, %f]", &read.r, &read.g, &read.b),
        3);
    EXPECT_TRUE(same_bits(read, tree.sample_value));
    EXPECT_NE(json.find("\"format\": \"glint-ray-tree\", \"version\": 1"), std::string::npos);
    EXPECT_NE(json.find("\"integrator\": \"distributed\""), std::string::npos);
    const std::string dot = ray_tree_dot(tree);
    EXPECT_EQ(dot.rfind("digraph ray_tree {", 0), 0u);
    EXPECT_NE(dot.find("ray0 ["), std::string::npos);
    EXPECT_EQ(dot.back(), '\n');
}

TEST(Explain, EachRayShowsTheFogItCrossed) {
    const Scene scene = small("scenes/features/fog.yaml", 1);
    const World world(scene);
    // The middle of the image: the eye ray meets the far floor or the sky through both fogs.
    const RayTree tree = explain(world, {12, 9, 0, 0});
    ASSERT_TRUE(tree.nodes[0].fog.has_value());
    const FogEffect& fog = *tree.nodes[0].fog;
    EXPECT_LT(fog.transmittance.g, 1);
    EXPECT_GT(fog.added.g, 0);
    EXPECT_TRUE(same_bits(evaluate(tree), tree.sample_value));
    EXPECT_NE(ray_tree_text(tree).find("through fog: lets "), std::string::npos);
    EXPECT_NE(ray_tree_json(tree).find("\"fog\": {\"transmittance\": ["), std::string::npos);
}

// Inside tinted glass that fades, the ray crossing it shows the fade as its fog, and its
// refracted branch the tint; the tree still gives the pixel exactly, for every integrator that
// records.
TEST(Explain, ARayInsideFadingGlassShowsItsFade) {
    for (const IntegratorKind kind :
         {IntegratorKind::whitted, IntegratorKind::distributed, IntegratorKind::path}) {
        Scene scene;
        scene.settings.width = scene.settings.height = 9;
        scene.settings.integrator = kind;
        scene.settings.samples_per_pixel = 1;
        scene.settings.background = {0.2f, 0.4f, 0.6f};
        scene.camera.from = {0, 0, -5};
        scene.camera.at = {0, 0, 0};
        Material glass;
        glass.ka = glass.kd = 0;
        glass.transmit = 0.8f;
        glass.ior = 1.5f;
        glass.tint = 1;
        glass.color = Color{1, 0.5f, 0.25f};
        glass.fade = {2, InteriorFade::kExponential, {0.5f, 1, 0}};
        scene.materials.push_back(glass);
        scene.objects.push_back({Sphere{{0, 0, 0}, 1}, 0});
        const World world(scene);
        const RayTree tree = explain(world, {4, 4, 0, 0});
        SCOPED_TRACE(std::string(integrator_info(kind).name));
        ASSERT_GE(tree.nodes.size(), 3u);
        EXPECT_FALSE(tree.nodes[0].fog.has_value());
        const RayNode& inside = tree.nodes[1];
        ASSERT_TRUE(inside.fog.has_value());
        EXPECT_TRUE(inside.fog_inside);
        EXPECT_LT(inside.fog->transmittance.b, inside.fog->transmittance.r);
        expect_every_node_evaluates_to_its_value(tree);
        EXPECT_TRUE(same_bits(evaluate(tree), tree.sample_value));
        EXPECT_NE(ray_tree_text(tree).find("through the object's inside: its fade lets "),
                  std::string::npos);
        EXPECT_NE(ray_tree_json(tree).find("\"inside\": true"), std::string::npos);
    }
}

}  // namespace
}  // namespace glint
