#include "glint/scene/yaml/yaml_scene_loader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <variant>

namespace glint::yaml_scene_loader_test {
namespace {

const std::filesystem::path kSourceDir = GLINT_SOURCE_DIR;

std::string read_text(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

Scene parse(const std::string& text) { return parse_yaml_scene(text, "test.yaml"); }

constexpr const char* kCamera = "camera: {from: [0, 0, -5], at: [0, 0, 0]}\n";

TEST(YamlScene, WhittedBasicsLoads) {
    const Scene scene = load_yaml_scene(kSourceDir / "scenes/whitted-basics.yaml");
    EXPECT_EQ(scene.settings.width, 320);
    EXPECT_EQ(scene.settings.height, 240);
    EXPECT_EQ(scene.settings.samples_per_pixel, 1);
    EXPECT_EQ(scene.settings.max_depth, 5);
    EXPECT_EQ(scene.settings.background, (Color{0.05f, 0.05f, 0.1f}));
    EXPECT_EQ(scene.camera.from, (Point3{0, 1.5f, -6}));
    EXPECT_EQ(scene.camera.fov, 45);
    EXPECT_EQ(scene.ambient, Color::gray(0.1f));

    ASSERT_EQ(scene.materials.size(), 3u);  // every object names one: no default is added
    EXPECT_EQ(scene.materials[0].name, "red");
    EXPECT_EQ(scene.materials[1].name, "mirror");
    EXPECT_EQ(scene.materials[2].name, "glass");
    EXPECT_EQ(scene.materials[1].reflect, 0.8f);
    EXPECT_EQ(scene.materials[2].transmit, 0.9f);
    EXPECT_EQ(scene.materials[2].ior, 1.5f);
    EXPECT_EQ(std::get<Color>(scene.materials[0].color), (Color{0.9f, 0.1f, 0.1f}));

    ASSERT_EQ(scene.lights.size(), 1u);
    EXPECT_EQ(std::get<PointLight>(scene.lights[0]).position, (Point3{-4, 6, -4}));

    ASSERT_EQ(scene.objects.size(), 5u);
    EXPECT_EQ(std::get<Sphere>(scene.objects[0].shape).radius, 1);
    EXPECT_EQ(scene.objects[0].material, 2u);
    EXPECT_EQ(scene.objects[1].material, 1u);
    EXPECT_EQ(scene.objects[2].material, 0u);
    EXPECT_TRUE(std::holds_alternative<Plane>(scene.objects[2].shape));
    EXPECT_EQ(std::get<Triangle>(scene.objects[3].shape).vertices[2], (Point3{-2, 2, 2}));
    EXPECT_EQ(std::get<Box>(scene.objects[4].shape).max, (Point3{-2.5f, 1, 0}));
}

TEST(YamlScene, DefaultsFillWhatTheFileLeavesOut) {
    const Scene scene = parse(std::string(kCamera) +
                              "objects:\n  - {type: sphere, center: [0, 0, 0], radius: 2}\n");
    const RenderSettings defaults;
    EXPECT_EQ(scene.settings.width, defaults.width);
    EXPECT_EQ(scene.settings.height, defaults.height);
    EXPECT_EQ(scene.settings.samples_per_pixel, 1);
    EXPECT_EQ(scene.settings.max_depth, 5);
    EXPECT_FLOAT_EQ(scene.settings.min_weight, 0.001f);
    EXPECT_EQ(scene.settings.background, Color());
    EXPECT_FALSE(scene.settings.transparent_shadows);
    EXPECT_EQ(scene.camera.projection, Projection::perspective);
    EXPECT_EQ(scene.camera.up, (Vector3{0, 1, 0}));
    EXPECT_EQ(scene.camera.fov, 45);
    EXPECT_EQ(scene.ambient, Color());
    EXPECT_TRUE(scene.lights.empty());

    // An object without a material gets the shared default, with the Material struct's values.
    ASSERT_EQ(scene.materials.size(), 1u);
    const Material& m = scene.materials[0];
    const Material reference;
    EXPECT_EQ(m.name, "default");
    EXPECT_EQ(m.ka, reference.ka);
    EXPECT_EQ(m.kd, reference.kd);
    EXPECT_EQ(m.shininess, reference.shininess);
    EXPECT_EQ(m.highlight, Highlight::blinn);
    ASSERT_EQ(scene.objects.size(), 1u);
    EXPECT_EQ(scene.objects[0].material, 0u);
    EXPECT_TRUE(scene.objects[0].casts_shadow);
}

TEST(YamlScene, SamplerAndFilterDefaultToTheIntegratorsChoice) {
    const Scene scene = parse(std::string(kCamera));
    EXPECT_EQ(scene.settings.integrator, IntegratorKind::whitted);
    EXPECT_FALSE(scene.settings.sampler);
    EXPECT_FALSE(scene.settings.filter);
    EXPECT_EQ(sampler_of(scene.settings), SamplerKind::regular);
    EXPECT_EQ(filter_of(scene.settings), FilterSpec{});
}

TEST(YamlScene, SamplerAndFilterAreRead) {
    const Scene named =
        parse(std::string(kCamera) + "image: {samples: 5, sampler: sobol, filter: mitchell}\n");
    EXPECT_EQ(named.settings.sampler, SamplerKind::sobol);
    EXPECT_EQ(named.settings.samples_per_pixel, 5);  // any count for sobol
    EXPECT_EQ(named.settings.filter->kind, FilterKind::mitchell);
    EXPECT_EQ(named.settings.filter->radius, 2);  // mitchell's default
    const Scene mapped =
        parse(std::string(kCamera) +
              "image: {sampler: jittered, filter: {type: gaussian, radius: 2, sigma: 0.75}}\n");
    EXPECT_EQ(mapped.settings.sampler, SamplerKind::jittered);
    EXPECT_EQ(mapped.settings.filter->kind, FilterKind::gaussian);
    EXPECT_EQ(mapped.settings.filter->radius, 2);
    EXPECT_EQ(mapped.settings.filter->sigma, 0.75f);
}

TEST(YamlScene, NoiseTexturesScalarMapsAndBumpsAreRead) {
    const Scene scene = parse(std::string(kCamera) + R"(
materials:
  stone:
    color: {type: marble, colors: [[1, 1, 1], [0, 0, 0], [0.5, 0.5, 0.5]], scale: 0.5, turbulence: 2, octaves: 4}
    reflect: {type: granite, low: 0.1, high: 0.4}
    roughness: {type: turbulence, high: 0.3, scale: 0.2}
    bump: {type: wood, strength: 0.02}
objects: [{type: sphere, center: [0, 0, 0], radius: 1, material: stone}]
)");
    EXPECT_FALSE(parse(std::string(kCamera) + "objects: [{type: sphere, center: [0, 0, 0], "
                                              "radius: 1, material: {reflect: 0.5}}]")
                     .materials.at(0)
                     .maps);  // constants only: no maps to look at
    const Material& m = scene.materials.at(0);
    const auto& color = std::get<NoiseTexture>(m.color);
    EXPECT_EQ(color.spec.pattern, NoisePattern::marble);
    EXPECT_EQ(color.spec.scale, 0.5f);
    EXPECT_EQ(color.spec.turbulence, 2);
    EXPECT_EQ(color.spec.octaves, 4);
    EXPECT_EQ(color.colors.size(), 3u);
    ASSERT_TRUE(m.maps);
    const MaterialMaps& maps = *m.maps;
    ASSERT_TRUE(maps.reflect);
    EXPECT_EQ(maps.reflect->spec.pattern, NoisePattern::granite);
    EXPECT_EQ(maps.reflect->low, 0.1f);
    EXPECT_EQ(maps.reflect->high, 0.4f);
    ASSERT_TRUE(maps.roughness);
    EXPECT_EQ(maps.roughness->low, 0);
    // transmit_roughness follows roughness, map and all.
    ASSERT_TRUE(maps.transmit_roughness);
    EXPECT_EQ(maps.transmit_roughness->spec.scale, 0.2f);
    ASSERT_TRUE(maps.bump);
    EXPECT_EQ(maps.bump->spec.pattern, NoisePattern::wood);
    EXPECT_EQ(maps.bump->strength, 0.02f);
}

// A CSG operand may show a material of its own (a name or a map); the others show the object's.
TEST(YamlScene, CsgOperandsMayHaveTheirOwnMaterials) {
    const Scene scene = parse(R"(
camera: {from: [0, 0, -5], at: [0, 0, 0]}
materials:
  red: {color: [1, 0, 0]}
objects:
  - type: difference
    material: {color: [0, 0, 1]}
    objects:
      - {type: box, min: [-1, -1, -1], max: [1, 1, 1]}
      - {type: sphere, center: [0, 0, -1], radius: 0.6, material: red}
      - {type: sphere, center: [0, 0, 1], radius: 0.6, material: {color: [0, 1, 0]}}
)");
    ASSERT_EQ(scene.objects.size(), 1u);
    const auto& difference = std::get<Csg>(scene.objects[0].shape);
    EXPECT_EQ(difference.material_a, 0u);  // the box: the object's own
    const auto& cutters = std::get<Csg>(*difference.b);
    const auto color_of = [&](std::uint32_t m) {
        return std::get<Color>(scene.materials[m - 1].color);
    };
    EXPECT_EQ(color_of(cutters.material_a), (Color{1, 0, 0}));
    EXPECT_EQ(color_of(cutters.material_b), (Color{0, 1, 0}));
    // A ray along z meets the first cutter's hollow first: its material, red.
    const auto hit = intersect(scene.objects[0].shape, Ray{{0, 0, -5}, {0, 0, 1}}, {0, kInfinity});
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(color_of(operand_material(scene.objects[0].shape, *hit)), (Color{1, 0, 0}));
}

TEST(YamlScene, ImageSettingsAreRead) {
    const Scene scene = parse(std::string(kCamera) +
                              "image:\n  width: 64\n  height: 32\n  samples: 16\n"
                              "  sampler: regular\n  max_depth: 12\n  min_weight: 0.25\n"
                              "  background: 0.5\n  transparent_shadows: true\n");
    EXPECT_EQ(scene.settings.width, 64);
    EXPECT_EQ(scene.settings.height, 32);
    EXPECT_EQ(scene.settings.samples_per_pixel, 16);
    EXPECT_EQ(scene.settings.sampler, SamplerKind::regular);
    EXPECT_EQ(scene.settings.max_depth, 12);
    EXPECT_EQ(scene.settings.min_weight, 0.25f);
    EXPECT_EQ(scene.settings.background, Color::gray(0.5f));  // one number is a gray
    EXPECT_TRUE(scene.settings.transparent_shadows);
}

TEST(YamlScene, OrthographicCameraAndNormalisedUp) {
    const Scene scene = parse(
        "camera: {type: orthographic, from: [1, 2, 3], at: [1, 2, 0], up: [0, 3, 0], "
        "height: 4.5}\n");
    EXPECT_EQ(scene.camera.projection, Projection::orthographic);
    EXPECT_EQ(scene.camera.from, (Point3{1, 2, 3}));
    EXPECT_EQ(scene.camera.at, (Point3{1, 2, 0}));
    EXPECT_EQ(scene.camera.up, (Vector3{0, 1, 0}));
    EXPECT_EQ(scene.camera.height, 4.5f);
}

// The wide projections with their own keys and defaults; a key of another projection, or an
// angle past a full turn, is an error.
TEST(YamlScene, WideCamerasTakeTheirOwnAngles) {
    const std::string at = "from: [0, 0, 0], at: [0, 0, 1]";
    EXPECT_EQ(parse("camera: {type: fisheye, " + at + "}\n").camera.fov, 180);
    EXPECT_EQ(parse("camera: {type: fisheye, fov: 360, " + at + "}\n").camera.fov, 360);
    EXPECT_EQ(parse("camera: {type: ultra_wide_angle, fov: 270, " + at + "}\n").camera.projection,
              Projection::ultra_wide_angle);
    EXPECT_EQ(parse("camera: {type: panoramic, " + at + "}\n").camera.projection,
              Projection::panoramic);
    const CameraSpec cylinder =
        parse(
            "camera: {type: cylindrical, fov: 120, height: 3, axis: horizontal, parallel: "
            "true, " +
            at + "}\n")
            .camera;
    EXPECT_EQ(cylinder.projection, Projection::cylindrical);
    EXPECT_EQ(cylinder.fov, 120);
    EXPECT_EQ(cylinder.height, 3);
    EXPECT_TRUE(cylinder.cylinder_axis_across);
    EXPECT_TRUE(cylinder.cylinder_parallel);
    const CameraSpec sphere =
        parse("camera: {type: spherical, vertical_fov: 90, " + at + "}\n").camera;
    EXPECT_EQ(sphere.fov, 360);
    EXPECT_EQ(sphere.vertical_fov, 90);
    for (const std::string bad :
         {"{type: fisheye, fov: 400, ", "{type: panoramic, fov: 20, ",
          "{type: spherical, height: 2, ", "{type: spherical, vertical_fov: 200, ",
          "{type: cylindrical, axis: diagonal, ", "{type: fisheye, f_number: 2, "})
        EXPECT_THROW(parse("camera: " + bad + at + "}\n"), SceneError) << bad;
}

TEST(YamlScene, NamedInlineAndDefaultMaterialsAreShared) {
    const Scene scene = parse(std::string(kCamera) +
                              "objects:\n"
                              "  - {type: sphere, center: [0, 0, 0], radius: 1, material: shiny}\n"
                              "  - {type: sphere, center: [3, 0, 0], radius: 1}\n"
                              "  - {type: sphere, center: [6, 0, 0], radius: 1,\n"
                              "     material: {color: [0, 1, 0], highlight: phong}}\n"
                              "  - {type: sphere, center: [9, 0, 0], radius: 1}\n"
                              "  - {type: sphere, center: [9, 0, 0], radius: 1, material: shiny}\n"
                              "materials:\n"  // after the objects: order in the file is free
                              "  shiny: {ks: 0.9, shininess: 80, emission: [0.1, 0, 0],\n"
                              "          brilliance: 3, metallic: 0.4}\n");
    ASSERT_EQ(scene.materials.size(), 3u);
    EXPECT_EQ(scene.materials[0].name, "shiny");
    EXPECT_EQ(scene.materials[0].ks, 0.9f);
    EXPECT_EQ(scene.materials[0].brilliance, 3);
    EXPECT_EQ(scene.materials[0].metallic, 0.4f);
    EXPECT_EQ(scene.materials[0].emission, (Color{0.1f, 0, 0}));
    EXPECT_EQ(scene.materials[1].name, "default");
    EXPECT_EQ(scene.materials[2].name, "(object 2)");
    EXPECT_EQ(std::get<Color>(scene.materials[2].color), (Color{0, 1, 0}));
    EXPECT_EQ(scene.materials[2].highlight, Highlight::phong);
    ASSERT_EQ(scene.objects.size(), 5u);
    EXPECT_EQ(scene.objects[0].material, 0u);
    EXPECT_EQ(scene.objects[1].material, 1u);
    EXPECT_EQ(scene.objects[2].material, 2u);
    EXPECT_EQ(scene.objects[3].material, 1u);
    EXPECT_EQ(scene.objects[4].material, 0u);
}

TEST(YamlScene, AMaterialNamedDefaultReplacesTheBuiltInOne) {
    const Scene scene = parse(std::string(kCamera) +
                              "materials: {default: {kd: 0.3}}\n"
                              "objects: [{type: box, min: [0, 0, 0], max: [1, 1, 1]}]\n");
    ASSERT_EQ(scene.materials.size(), 1u);
    EXPECT_EQ(scene.materials[0].kd, 0.3f);
    EXPECT_EQ(scene.objects[0].material, 0u);
}

TEST(YamlScene, CheckerTexture) {
    const Scene scene = parse(std::string(kCamera) +
                              "materials:\n"
                              "  floor: {color: {type: checker, even: 1, odd: [0.2, 0, 0], "
                              "size: 0.5, space: uv}}\n"
                              "  plain: {color: {type: checker}}\n");
    const auto& checker = std::get<CheckerTexture>(scene.materials[0].color);
    EXPECT_EQ(checker.even, Color::gray(1));
    EXPECT_EQ(checker.odd, (Color{0.2f, 0, 0}));
    EXPECT_EQ(checker.size, 0.5f);
    EXPECT_EQ(checker.space, CheckerSpace::uv);
    const auto& defaults = std::get<CheckerTexture>(scene.materials[1].color);
    EXPECT_EQ(defaults.even, Color::gray(1));
    EXPECT_EQ(defaults.odd, Color());
    EXPECT_EQ(defaults.size, 1);
    EXPECT_EQ(defaults.space, CheckerSpace::solid);
}

TEST(YamlScene, LightsScaleColorByIntensityAndNormaliseDirections) {
    const Scene scene = parse(std::string(kCamera) +
                              "lights:\n"
                              "  - {type: point, position: [1, 2, 3], color: [1, 0.5, 0], "
                              "intensity: 2, attenuation: [0, 0, 1]}\n"
                              "  - {type: directional, direction: [0, -2, 0], shadows: false}\n"
                              "  - {type: point, position: [0, 0, 0]}\n");
    ASSERT_EQ(scene.lights.size(), 3u);
    const auto& point = std::get<PointLight>(scene.lights[0]);
    EXPECT_EQ(point.position, (Point3{1, 2, 3}));
    EXPECT_EQ(point.color, (Color{2, 1, 0}));
    EXPECT_EQ(point.attenuation.constant, 0);
    EXPECT_EQ(point.attenuation.quadratic, 1);
    const auto& sun = std::get<DirectionalLight>(scene.lights[1]);
    EXPECT_EQ(sun.direction, (Vector3{0, -1, 0}));
    EXPECT_EQ(sun.color, Color::gray(1));
    EXPECT_FALSE(sun.casts_shadows);
    EXPECT_TRUE(point.casts_shadows);
    const auto& plain = std::get<PointLight>(scene.lights[2]);
    EXPECT_EQ(plain.color, Color::gray(1));
    EXPECT_EQ(plain.attenuation.constant, 1);
    EXPECT_EQ(plain.attenuation.linear, 0);
}

TEST(YamlScene, ShapesAreReadAndPlaneNormalsNormalised) {
    const Scene scene = parse(std::string(kCamera) +
                              "objects:\n"
                              "  - type: plane\n"
                              "    point: [0, -1, 0]\n"
                              "    normal: [0, 0, 5]\n"
                              "    casts_shadow: false\n"
                              "  - type: triangle\n"
                              "    vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]]\n"
                              "    uvs: [[0, 0], [2, 0], [0, 2]]\n"
                              "  - {type: box, min: [-1, -2, -3], max: [1, 2, 3]}\n");
    ASSERT_EQ(scene.objects.size(), 3u);
    const auto& plane = std::get<Plane>(scene.objects[0].shape);
    EXPECT_EQ(plane.point, (Point3{0, -1, 0}));
    EXPECT_EQ(plane.normal, (Normal3{0, 0, 1}));
    EXPECT_FALSE(scene.objects[0].casts_shadow);
    const auto& triangle = std::get<Triangle>(scene.objects[1].shape);
    EXPECT_EQ(triangle.vertices[1], (Point3{1, 0, 0}));
    EXPECT_EQ(triangle.uvs[2], (Point2{0, 2}));
    const auto& box = std::get<Box>(scene.objects[2].shape);
    EXPECT_EQ(box.min, (Point3{-1, -2, -3}));
    EXPECT_EQ(box.max, (Point3{1, 2, 3}));
}

// A glTF file placed as a mesh object gives triangles and materials; its cameras and lights are
// not the scene's, and a warning names the file and what it leaves out.
TEST(YamlScene, MeshObjectFromGltfWarnsOfTheCamerasAndLightsItIgnores) {
    const std::string scene_file = (kSourceDir / "tests/data/meshes/inline.yaml").string();
    const Scene scene = parse_yaml_scene(
        "camera: {from: [0, 0, -5], at: [0, 0, 0]}\n"
        "objects:\n"
        "  - {type: mesh, file: quad.gltf}\n"
        "  - {type: mesh, file: quad.gltf, transform: [{translate: [2, 0, 0]}]}\n",
        scene_file);
    EXPECT_TRUE(scene.lights.empty());
    std::vector<std::string> about_gltf;
    for (const std::string& w : scene.warnings)
        if (w.find("ignored") != std::string::npos) about_gltf.push_back(w);
    ASSERT_EQ(about_gltf.size(), 1u);  // once per file, however often it is used
    EXPECT_EQ(about_gltf[0],
              (kSourceDir / "tests/data/meshes/quad.gltf").string() +
                  ": 1 camera and 3 lights of the file ignored: as a mesh object (" + scene_file +
                  ":3:24) it gives only its triangles and materials; render the file on its own "
                  "to use them");
    // A file without cameras or lights gives no such warning.
    const Scene ply = parse_yaml_scene(
        "camera: {from: [0, 0, -5], at: [0, 0, 0]}\nobjects: [{type: mesh, file: "
        "cube_ascii.ply}]\n",
        scene_file);
    EXPECT_TRUE(ply.warnings.empty());
}

TEST(YamlScene, EmptySectionsAreAllowed) {
    const Scene scene = parse(std::string(kCamera) + "image:\nmaterials:\nlights: []\nobjects:\n");
    EXPECT_TRUE(scene.objects.empty());
    EXPECT_TRUE(scene.materials.empty());
}

TEST(YamlScene, CrlfLineEndingsAndCommentsAreFine) {
    const Scene scene = parse(
        "# a comment\r\ncamera:\r\n  from: [0, 0, -1] # eye\r\n"
        "  at: [0, 0, 0]\r\n");
    EXPECT_EQ(scene.camera.from, (Point3{0, 0, -1}));
}

TEST(YamlScene, EmptyTextIsAnErrorWithoutALine) {
    try {
        parse("");
        FAIL() << "expected a SceneError";
    } catch (const SceneError& e) {
        EXPECT_EQ(e.location().line, 0);
        EXPECT_EQ(e.message(), "the scene is empty; it needs at least a camera");
    }
}

TEST(YamlScene, MissingFileGivesAnErrorWithoutALine) {
    const std::filesystem::path path = kSourceDir / "scenes/no-such-scene.yaml";
    try {
        load_yaml_scene(path);
        FAIL() << "expected a SceneError";
    } catch (const SceneError& e) {
        EXPECT_EQ(e.location().line, 0);
        EXPECT_EQ(format_scene_error(e), path.string() +
                                             ": error: cannot read scene file: No such file or "
                                             "directory\n");
    }
}

TEST(YamlScene, DirectoryIsNotASceneFile) {
    try {
        load_yaml_scene(kSourceDir / "scenes");
        FAIL() << "expected a SceneError";
    } catch (const SceneError& e) {
        EXPECT_EQ(e.message(), "cannot read scene file: it is a directory");
    }
}

TEST(YamlScene, OversizedFileIsRefusedBeforeReading) {
    const std::filesystem::path dir = GLINT_TEST_OUTPUT_DIR;
    std::filesystem::create_directories(dir);
    const std::filesystem::path path = dir / "huge.yaml";
    {
        std::ofstream out(path, std::ios::binary);
        out << kCamera;
    }
    // A sparse file: its size is over the limit without writing 64 MiB.
    std::filesystem::resize_file(path, kMaxSceneFileBytes + 1);
    try {
        load_yaml_scene(path);
        FAIL() << "expected a SceneError";
    } catch (const SceneError& e) {
        EXPECT_EQ(e.location().line, 0);
        EXPECT_EQ(e.message(), "scene file is larger than the limit of 64 MiB");
    }
    std::filesystem::remove(path);
}

TEST(YamlScene, DeepNestingIsAnErrorNotAStackOverflow) {
    for (const std::string opener : {"[", "{a: ", "- "}) {
        std::string text = "camera: ";
        for (int i = 0; i < 100000; ++i) text += opener;
        EXPECT_THROW(parse(text), SceneError) << opener;
    }
}

// Every prefix of a valid scene is either a valid scene or a SceneError: never another exception
// or a crash.
TEST(YamlScene, EveryTruncationParsesOrThrowsSceneError) {
    const std::string text = read_text(kSourceDir / "scenes/whitted-basics.yaml");
    ASSERT_FALSE(text.empty());
    int errors = 0;
    for (std::size_t n = 0; n <= text.size(); ++n) {
        try {
            parse(text.substr(0, n));
        } catch (const SceneError& e) {
            ++errors;
            EXPECT_FALSE(e.message().empty());
            EXPECT_FALSE(format_scene_error(e).empty());
        } catch (const std::exception& e) {
            ADD_FAILURE() << "prefix of " << n << " bytes threw " << e.what();
        }
    }
    EXPECT_GT(errors, 0);
}

// The same for a scene whose bytes are replaced one at a time by characters that YAML treats
// specially.
TEST(YamlScene, EverySingleByteCorruptionParsesOrThrowsSceneError) {
    const std::string text = read_text(kSourceDir / "scenes/whitted-basics.yaml");
    for (std::size_t i = 0; i < text.size(); ++i) {
        for (const char c : {'{', ']', ',', '*', '\0', '"'}) {
            std::string corrupt = text;
            corrupt[i] = c;
            try {
                parse(corrupt);
            } catch (const SceneError&) {
            } catch (const std::exception& e) {
                ADD_FAILURE() << "byte " << i << " set to " << int(c) << " threw " << e.what();
            }
        }
    }
}

// Keys that load but do nothing are warned about at their place in the file.
TEST(YamlScene, ALensShapeOnAPinholeCameraIsWarnedAbout) {
    const Scene pinhole = parse(
        "camera: {from: [0, 0, -5], at: [0, 0, 0], aperture_blades: 6,\n"
        "         aperture_rotation: 30, focus_distance: 4}\n");
    ASSERT_EQ(pinhole.warnings.size(), 3u);
    EXPECT_EQ(pinhole.warnings[0],
              "test.yaml:2:33: camera focus_distance does nothing without an aperture: a pinhole "
              "camera has no lens (give aperture or f_number for depth of field)");
    EXPECT_EQ(pinhole.warnings[1].substr(0, 43), "test.yaml:1:43: camera aperture_blades does");
    EXPECT_EQ(pinhole.warnings[2].substr(0, 45), "test.yaml:2:10: camera aperture_rotation does");
    // With an aperture they shape the lens; a zero aperture is a pinhole too.
    EXPECT_TRUE(parse("camera: {from: [0, 0, -5], at: [0, 0, 0], aperture: 0.1, "
                      "aperture_blades: 6}\n")
                    .warnings.empty());
    EXPECT_EQ(parse("camera: {from: [0, 0, -5], at: [0, 0, 0], aperture: 0, "
                    "aperture_blades: 6}\n")
                  .warnings.size(),
              1u);
}

TEST(YamlScene, EmitsLightOnAMaterialWithoutEmissionIsWarnedAbout) {
    const auto ball = [](const std::string& rest) {
        return "  - {type: sphere, center: [0, 0, 0], radius: 1, " + rest + "}\n";
    };
    const Scene dark = parse(std::string(kCamera) +
                             "materials: {grey: {kd: 0.5}, lamp: {emission: [1, 1, 1]}}\n"
                             "objects:\n" +
                             ball("material: grey, emits_light: true") +
                             ball("material: lamp, emits_light: true") +
                             ball("material: lamp, emits_light: false") + ball("material: grey"));
    ASSERT_EQ(dark.warnings.size(), 1u);
    EXPECT_EQ(dark.warnings[0],
              "test.yaml:4:66: emits_light does nothing: the object's material has no emission "
              "(give the material an emission for it to light the scene)");
}

}  // namespace
}  // namespace glint::yaml_scene_loader_test
