// Output variables: the image's parts add up to it; what the eye ray hit is recorded with the
// notes' numbers and averaged over the samples that hit; ids, tree depth, samples and traversal
// counts; asking for them leaves the image as it was, bit for bit.
#include "glint/render/film/aov.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

#include "glint/image/colour_map.h"
#include "glint/render/film/aov_picture.h"
#include "glint/render/memory_estimate.h"
#include "glint/render/render.h"
#include "glint/scene/load_scene.h"
#include "recorder_test_scenes.h"

namespace glint {
namespace {

bool same_bits(const Image& a, const Image& b) {
    return a.pixels.size() == b.pixels.size() &&
           std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(Color)) == 0;
}

const Image& layer(const RenderResult& r, Aov a) {
    for (const AovImage& l : r.aovs)
        if (l.aov == a) return l.image;
    throw std::logic_error("no layer " + std::string(aov_info(a).name));
}

RenderResult render_with(const Scene& scene, AovSet aovs, AccelKind accel = AccelKind::bvh) {
    const World world(scene, accel);
    RenderOptions options;
    options.seed = 3;
    options.aovs = aovs;
    return render(world, options);
}

AovSet all_but_counts() { return parse_aov_list("contributions,surface,ids,tree_depth,samples"); }

TEST(AovList, NamesAndGroups) {
    const AovSet set = parse_aov_list("depth,normal");
    EXPECT_EQ(set.list(), (std::vector<Aov>{Aov::depth, Aov::normal}));
    EXPECT_EQ(
        parse_aov_list("contributions").list(),
        (std::vector<Aov>{Aov::emission, Aov::ambient, Aov::diffuse, Aov::specular, Aov::reflected,
                          Aov::refracted, Aov::direct, Aov::indirect, Aov::fog}));
    EXPECT_EQ(parse_aov_list("ids").list(), (std::vector<Aov>{Aov::object, Aov::material}));
    EXPECT_EQ(parse_aov_list("surface,uv").list().size(), 5u);
    EXPECT_EQ(parse_aov_list("all").list().size(), counts_traversal() ? kAovCount : kAovCount - 2);
    try {
        parse_aov_list("depth,colour");
        FAIL();
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("unknown output variable 'colour'"),
                  std::string::npos);
    }
    EXPECT_THROW(parse_aov_list(""), std::invalid_argument);
    EXPECT_THROW(parse_aov_list("depth,"), std::invalid_argument);
    if (!counts_traversal()) {
        try {
            parse_aov_list("cost");
            FAIL();
        } catch (const std::invalid_argument& e) {
            EXPECT_NE(std::string(e.what()).find("-DGLINT_TRAVERSAL_COUNTERS=ON"),
                      std::string::npos);
        }
    }
}

Scene small(const std::string& file) {
    Scene scene = load_scene(std::string(GLINT_SOURCE_DIR) + "/" + file);
    scene.settings.width = 32;
    scene.settings.height = 24;
    scene.settings.samples_per_pixel = 4;
    if (!is_valid_sample_count(sampler_of(scene.settings), 4))
        scene.settings.sampler = SamplerKind::jittered;
    return scene;
}

class AovScenes : public ::testing::TestWithParam<const char*> {};

TEST_P(AovScenes, ContributionsAddUpToTheImageWhichStaysAsItWas) {
    const Scene scene = small(GetParam());
    const RenderResult plain = render_with(scene, {});
    const RenderResult r = render_with(scene, all_but_counts());
    EXPECT_TRUE(same_bits(r.image, plain.image)) << "the recorder changed the image";
    // Whitted's parts, and the path tracer's.
    const Aov parts[] = {Aov::emission,  Aov::ambient, Aov::diffuse,  Aov::specular, Aov::reflected,
                         Aov::refracted, Aov::direct,  Aov::indirect, Aov::fog};
    float largest_part = 0;
    for (std::size_t i = 0; i < r.image.pixels.size(); ++i) {
        Color sum;
        for (const Aov a : parts) sum += layer(r, a).pixels[i];
        const Color& pixel = r.image.pixels[i];
        // Each layer's fixed-point sums round on their own; floats add in another order.
        const auto tolerance = [](float v) { return 1e-5f + 1e-5f * std::abs(v); };
        ASSERT_NEAR(sum.r, pixel.r, tolerance(pixel.r)) << GetParam() << " pixel " << i;
        ASSERT_NEAR(sum.g, pixel.g, tolerance(pixel.g)) << GetParam() << " pixel " << i;
        ASSERT_NEAR(sum.b, pixel.b, tolerance(pixel.b)) << GetParam() << " pixel " << i;
        for (const Aov a : {Aov::diffuse, Aov::reflected, Aov::refracted, Aov::direct})
            largest_part = std::max(largest_part, layer(r, a).pixels[i].g);
    }
    EXPECT_GT(largest_part, 0) << "nothing but emission and ambient";
    for (std::size_t i = 0; i < r.image.pixels.size(); ++i)
        EXPECT_EQ(layer(r, Aov::samples).pixels[i], Color::gray(4));
}

INSTANTIATE_TEST_SUITE_P(Scenes, AovScenes, ::testing::ValuesIn(testing::kRecorderTestScenes),
                         testing::scene_test_name);

// Camera at z = -5 looking at a unit sphere at the origin (material 1; material 0 unused), one
// sample per pixel at the pixel's centre, a one-pixel box: each pixel is its eye ray's.
Scene sphere_scene() {
    Scene scene;
    scene.settings.width = scene.settings.height = 9;
    scene.settings.samples_per_pixel = 1;
    scene.settings.sampler = SamplerKind::regular;
    scene.settings.filter = FilterSpec{FilterKind::box, 0.5f};
    scene.camera.from = {0, 0, -5};
    scene.camera.at = {0, 0, 0};
    scene.camera.fov = 30;
    scene.materials.push_back(Material{});
    Material m;
    m.color = Color{0.8f, 0.4f, 0.2f};
    scene.materials.push_back(m);
    scene.objects.push_back({Sphere{{0, 0, 0}, 1}, 1});
    return scene;
}

TEST(Aovs, TheEyeRaysHitAtTheCentreWithTheNotesNumbers) {
    const Scene scene = sphere_scene();
    const RenderResult r = render_with(scene, parse_aov_list("surface,ids,tree_depth"));
    // The centre pixel's ray runs along +z and meets the sphere at (0, 0, -1), 4 from the eye,
    // where the normal faces it: (0, 0, -1).
    const Color depth = layer(r, Aov::depth).at(4, 4), p = layer(r, Aov::position).at(4, 4),
                n = layer(r, Aov::normal).at(4, 4);
    EXPECT_NEAR(depth.r, 4, 1e-5f);
    EXPECT_NEAR(p.r, 0, 1e-5f);
    EXPECT_NEAR(p.g, 0, 1e-5f);
    EXPECT_NEAR(p.b, -1, 1e-5f);
    EXPECT_NEAR(n.r, 0, 1e-5f);
    EXPECT_NEAR(n.g, 0, 1e-5f);
    EXPECT_NEAR(n.b, -1, 1e-5f);
    EXPECT_EQ(layer(r, Aov::albedo).at(4, 4), (Color{0.8f, 0.4f, 0.2f}));
    const Color uv = layer(r, Aov::uv).at(4, 4);
    EXPECT_TRUE(uv.r >= 0 && uv.r <= 1 && uv.g >= 0 && uv.g <= 1 && uv.b == 0);
    EXPECT_EQ(layer(r, Aov::object).at(4, 4), Color::gray(0));
    EXPECT_EQ(layer(r, Aov::material).at(4, 4), Color::gray(1));
    EXPECT_EQ(layer(r, Aov::tree_depth).at(4, 4), Color::gray(1));
    // The corner's ray misses: nothing hit, ids -1.
    EXPECT_EQ(layer(r, Aov::depth).at(0, 0), Color{});
    EXPECT_EQ(layer(r, Aov::normal).at(0, 0), Color{});
    EXPECT_EQ(layer(r, Aov::object).at(0, 0), Color::gray(-1));
    EXPECT_EQ(layer(r, Aov::material).at(0, 0), Color::gray(-1));
    EXPECT_EQ(layer(r, Aov::tree_depth).at(0, 0), Color::gray(1));
}

TEST(Aovs, SurfaceVariablesAverageOnlyTheSamplesThatHit) {
    // 64 jittered samples through a wide Gaussian: silhouette pixels mix hits and misses. Their
    // depth stays within the sphere's, 4 to 5 from the eye, where a mean over every sample
    // would fall towards 0.
    Scene scene = sphere_scene();
    scene.settings.samples_per_pixel = 64;
    scene.settings.sampler = SamplerKind::jittered;
    scene.settings.filter = FilterSpec{FilterKind::gaussian, 1.5f};
    scene.materials[1].emission = Color::gray(1);  // the image is the sphere's coverage
    const RenderResult r = render_with(scene, parse_aov_list("depth,normal"));
    int edge_pixels = 0;
    for (int y = 0; y < 9; ++y)
        for (int x = 0; x < 9; ++x) {
            const float d = layer(r, Aov::depth).at(x, y).r;
            if (d == 0) continue;
            EXPECT_GE(d, 4 - 1e-4f) << x << "," << y;
            EXPECT_LE(d, 5 + 1e-4f) << x << "," << y;
            const Color n = layer(r, Aov::normal).at(x, y);
            EXPECT_LE(n.r * n.r + n.g * n.g + n.b * n.b, 1 + 1e-4f);
            const float coverage = r.image.at(x, y).r;
            edge_pixels += coverage > 0.01f && coverage < 0.99f;
        }
    EXPECT_GT(edge_pixels, 0);
}

TEST(Aovs, TreeDepthCountsTheReflectedRay) {
    // A mirror sphere in a void: the eye ray and its reflection, which misses: depth 2.
    Scene scene = sphere_scene();
    scene.materials[1].reflect = 0.5f;
    scene.settings.background = Color::gray(0.4f);
    const RenderResult r = render_with(scene, parse_aov_list("tree_depth,reflected,emission"));
    EXPECT_EQ(layer(r, Aov::tree_depth).at(4, 4), Color::gray(2));
    EXPECT_EQ(layer(r, Aov::tree_depth).at(0, 0), Color::gray(1));
    EXPECT_NEAR(layer(r, Aov::reflected).at(4, 4).r, 0.5f * 0.4f, 1e-6f);  // kr I(background)
    EXPECT_NEAR(layer(r, Aov::emission).at(0, 0).r, 0.4f, 1e-6f);          // the background, seen
    EXPECT_EQ(layer(r, Aov::emission).at(4, 4), Color{});
}

TEST(Aovs, DiffuseAndSpecularSplitEachLightsTerm) {
    // Light from the eye: at the front N = L = V, the diffuse term IL kd C (N.L) and the
    // highlight IL ks (N.H)^n = IL ks.
    Scene scene = sphere_scene();
    Material& m = scene.materials[1];
    m.ka = 0, m.kd = 0.6f, m.ks = 0.3f, m.shininess = 7;
    scene.lights.push_back(DirectionalLight{{0, 0, 1}, Color::gray(0.8f)});
    const RenderResult r = render_with(scene, parse_aov_list("diffuse,specular"));
    const Color d = layer(r, Aov::diffuse).at(4, 4), s = layer(r, Aov::specular).at(4, 4);
    EXPECT_NEAR(d.r, 0.8f * 0.6f * 0.8f, 1e-5f);
    EXPECT_NEAR(d.g, 0.8f * 0.6f * 0.4f, 1e-5f);
    EXPECT_NEAR(d.b, 0.8f * 0.6f * 0.2f, 1e-5f);
    EXPECT_NEAR(s.r, 0.8f * 0.3f, 1e-5f);
    EXPECT_NEAR(s.b, 0.8f * 0.3f, 1e-5f);
}

TEST(Aovs, IdsAreThoseOfThePixelsFirstSample) {
    Scene scene = sphere_scene();
    scene.settings.samples_per_pixel = 16;
    scene.settings.sampler = SamplerKind::jittered;
    const RenderResult r = render_with(scene, parse_aov_list("object"));
    for (const Color& c : layer(r, Aov::object).pixels) EXPECT_TRUE(c.r == 0 || c.r == -1);
}

TEST(Aovs, CountTheNodesAndPrimitivesEachSampleTests) {
    if (!counts_traversal()) GTEST_SKIP() << "built without -DGLINT_TRAVERSAL_COUNTERS=ON";
    // 32 spheres in a row, no lights, no mirrors: each eye ray is the sample's only ray. A list
    // tests every sphere and visits no node; a BVH visits nodes and tests fewer (a few spheres
    // would be one leaf of blocks, which every ray tests).
    Scene scene = sphere_scene();
    constexpr int kSpheres = 32;
    for (int i = 1; i < kSpheres; ++i)
        scene.objects.push_back({Sphere{{float(3 * i), 0, 0}, 1}, 1});
    const AovSet cost = parse_aov_list("cost");
    const RenderResult list = render_with(scene, cost, AccelKind::list);
    for (std::size_t i = 0; i < list.image.pixels.size(); ++i) {
        EXPECT_EQ(layer(list, Aov::primitives).pixels[i], Color::gray(kSpheres));
        EXPECT_EQ(layer(list, Aov::nodes).pixels[i], Color{});
    }
    const RenderResult bvh = render_with(scene, cost, AccelKind::bvh);
    float nodes = 0, tested = 0;
    for (std::size_t i = 0; i < bvh.image.pixels.size(); ++i) {
        nodes += layer(bvh, Aov::nodes).pixels[i].r;
        tested += layer(bvh, Aov::primitives).pixels[i].r;
    }
    EXPECT_GT(nodes, 0);
    EXPECT_LT(tested, float(kSpheres) * float(bvh.image.pixels.size()));
}

TEST(Aovs, PicturesGetALegendStripAndTheirMap) {
    AovImage depth{Aov::depth, Image(64, 8)};
    for (int x = 0; x < 64; ++x) depth.image.at(x, 2) = Color::gray(4 + float(x) / 63);
    const Image picture = aov_picture(depth);
    EXPECT_EQ(picture.width, 64);
    EXPECT_EQ(picture.height, 8 + 13);     // a strip of 7-pixel text and 3 above and below
    EXPECT_EQ(picture.at(0, 0), Color{});  // no hit: black
    // The 1st to 99th percentiles: the lowest pixels and the highest at the map's ends.
    EXPECT_EQ(picture.at(0, 2), colour_map(0));
    EXPECT_EQ(picture.at(63, 2), colour_map(1));
    AovImage ids{Aov::object, Image(4, 1)};
    ids.image.pixels = {Color::gray(-1), Color::gray(0), Color::gray(7), Color::gray(7)};
    const Image id_picture = aov_picture(ids);
    EXPECT_EQ(id_picture.at(0, 0), Color{});
    EXPECT_EQ(id_picture.at(1, 0), id_colour(0));
    EXPECT_EQ(id_picture.at(3, 0), id_colour(7));
}

TEST(Aovs, MemoryEstimateCountsEachVariablesFilm) {
    Scene scene = sphere_scene();
    scene.settings.width = 100;
    scene.settings.height = 10;  // 1000 pixels, the one-pixel box: 16-byte sums
    const std::uint64_t none = estimate_render_memory(scene, AccelKind::bvh).film;
    const std::uint64_t with =
        estimate_render_memory(scene, AccelKind::bvh, {.aovs = parse_aov_list("depth,object")})
            .film;
    // Depth: a 16-byte sum, its layer and the copy written, 24 each; object: a 4-byte id and the
    // same two images.
    EXPECT_EQ(with - none, 1000u * ((16 + 24) + (4 + 24)));
}

}  // namespace
}  // namespace glint
