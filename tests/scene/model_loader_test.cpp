// Importing the good test meshes of tests/data/meshes: counts, transforms, materials, lights,
// cameras, textures, normals and warnings.
#include "glint/scene/mesh/model_loader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "glint/math/constants.h"
#include "glint/scene/scene_error.h"
#include "glint/shading/texture.h"

namespace glint::model_loader_test {
namespace {

const std::filesystem::path kMeshes = std::filesystem::path(GLINT_SOURCE_DIR) / "tests/data/meshes";

Model load(const std::string& name, const ModelOptions& options = {}) {
    try {
        return load_model(kMeshes / name, options);
    } catch (const SceneError& e) {
        ADD_FAILURE() << format_scene_error(e);
        return {};
    }
}

std::size_t triangle_count(const Model& m) {
    std::size_t n = 0;
    for (const ModelPart& p : m.parts) n += p.mesh->triangles.size();
    return n;
}

std::optional<std::pair<ShapeHit, const ModelPart*>> intersect(const Model& m, const Ray& ray) {
    std::optional<std::pair<ShapeHit, const ModelPart*>> nearest;
    Interval range;
    for (const ModelPart& p : m.parts) {
        if (auto hit = TriangleMesh{p.mesh}.intersect(ray, range)) {
            range.max = hit->t;
            nearest = {{*hit, &p}};
        }
    }
    return nearest;
}

bool has_warning(const Model& m, const std::string& text) {
    return std::any_of(m.warnings.begin(), m.warnings.end(),
                       [&](const std::string& w) { return w.find(text) != std::string::npos; });
}

void expect_point(Point3 p, Point3 expected, float tolerance = 1e-5f) {
    EXPECT_NEAR(p.x, expected.x, tolerance);
    EXPECT_NEAR(p.y, expected.y, tolerance);
    EXPECT_NEAR(p.z, expected.z, tolerance);
}

TEST(ModelLoader, GltfNodeTransformsAndMirroring) {
    const Model m = load("quad.gltf");
    EXPECT_EQ(triangle_count(m), 4u);  // the quad twice: two nodes use it
    expect_point(m.bounds.min, {-12, 0, 0});
    expect_point(m.bounds.max, {12, 2, 0});
    // Both copies face +z: the mirrored node's winding is turned back.
    for (const float x : {11.0f, -11.0f}) {
        const Ray ray{{x, 1, 3}, {0, 0, -1}};
        const auto hit = intersect(m, ray);
        ASSERT_TRUE(hit) << x;
        const SurfacePoint sp = TriangleMesh{hit->second->mesh}.surface_at(ray, hit->first);
        EXPECT_EQ(sp.normal, (Normal3{0, 0, 1})) << x;
        EXPECT_NEAR(sp.shading_normal.z, 1, 1e-6f) << x;  // the file's normals, transformed
    }
}

TEST(ModelLoader, GltfMetallicRoughnessMaterial) {
    const Model m = load("quad.gltf");
    ASSERT_EQ(m.materials.size(), 1u);
    const Material& mat = m.materials[0];
    EXPECT_EQ(mat.name, "red_metal");
    EXPECT_EQ(std::get<Color>(mat.color), (Color{0.8f, 0.2f, 0.1f}));
    EXPECT_EQ(mat.kd, 1);
    // roughness 0.5: ks = 1 - 0.5; alpha = 0.25, n = 2 / 0.0625 - 2 = 30;
    // reflect = metallic (1 - roughness) = 0.5 * 0.5.
    EXPECT_FLOAT_EQ(mat.ks, 0.5f);
    EXPECT_FLOAT_EQ(mat.shininess, 30);
    EXPECT_FLOAT_EQ(mat.reflect, 0.25f);
    EXPECT_EQ(mat.transmit, 0);
    EXPECT_EQ(mat.ior, 1);
    EXPECT_EQ(mat.emission, (Color{0.1f, 0.2f, 0.3f}));
}

TEST(ModelLoader, GltfPunctualLights) {
    const Model m = load("quad.gltf");
    ASSERT_EQ(m.lights.size(), 3u);
    const auto& bulb = std::get<PointLight>(m.lights[0]);
    expect_point(bulb.position, {0, 3, 0});
    EXPECT_EQ(bulb.color, (Color{20, 10, 5}));  // colour x intensity 20, 1:1
    EXPECT_EQ(bulb.attenuation.constant, 0);
    EXPECT_EQ(bulb.attenuation.linear, 0);
    EXPECT_EQ(bulb.attenuation.quadratic, 1);
    const auto& sun = std::get<DirectionalLight>(m.lights[1]);
    EXPECT_NEAR(sun.direction.x, 0, 1e-6f);  // the node turns -z to -y
    EXPECT_NEAR(sun.direction.y, -1, 1e-6f);
    EXPECT_NEAR(sun.direction.z, 0, 1e-6f);
    EXPECT_EQ(sun.color, (Color{2, 2, 2}));
    const auto& spot = std::get<PointLight>(m.lights[2]);
    expect_point(spot.position, {1, 2, 3});
    EXPECT_EQ(spot.color, (Color{10, 10, 10}));
    EXPECT_TRUE(has_warning(m, "spot light \"spot_node\" imported as a point light"));
}

TEST(ModelLoader, GltfPerspectiveCamera) {
    const Model m = load("quad.gltf");
    ASSERT_EQ(m.cameras.size(), 1u);
    const CameraSpec& c = m.cameras[0].spec;
    EXPECT_EQ(m.cameras[0].name, "eye");
    EXPECT_EQ(c.projection, Projection::perspective);
    expect_point(c.from, {11, 1, 5});
    expect_point(c.at, {11, 1, 4});
    EXPECT_NEAR(c.up.y, 1, 1e-6f);
    EXPECT_NEAR(c.fov, degrees(0.8f), 1e-4f);  // yfov 0.8 rad = 45.837 degrees
}

TEST(ModelLoader, GlbWithEmbeddedTextureAndOrthographicCamera) {
    const Model m = load("quad.glb");
    ASSERT_EQ(m.cameras.size(), 1u);
    EXPECT_EQ(m.cameras[0].spec.projection, Projection::orthographic);
    EXPECT_FLOAT_EQ(m.cameras[0].spec.height, 4);  // 2 ymag
    ASSERT_EQ(m.materials.size(), 1u);
    const auto* texture = std::get_if<ImageTexture>(&m.materials[0].color);
    ASSERT_TRUE(texture);
    EXPECT_EQ(texture->image->base().width, 2);
    EXPECT_EQ(texture->scale, (Color{0.8f, 0.2f, 0.1f}));          // baseColorFactor
    EXPECT_EQ(texture->image->base().at(0, 0), (Color{1, 0, 0}));  // top left: red
    EXPECT_EQ(texture->image->base().at(0, 1), (Color{0, 0, 1}));  // bottom left: blue
    // glTF uv (0.25, 0.25), near vertex 0 at (10, 0, 0), is the top-left texel: red. glTF's v
    // runs down the image; Assimp turns it to glint's convention.
    const Ray ray{{10.5f, 0.5f, 1}, {0, 0, -1}};
    const auto hit = intersect(m, ray);
    ASSERT_TRUE(hit);
    const SurfacePoint sp = TriangleMesh{hit->second->mesh}.surface_at(ray, hit->first);
    const Color c = evaluate(m.materials[0].color, sp);
    EXPECT_NEAR(c.r, 0.8f, 1e-5f);
    EXPECT_NEAR(c.g, 0, 1e-5f);
    EXPECT_NEAR(c.b, 0, 1e-5f);
}

TEST(ModelLoader, PlyAsciiAndBinaryGiveTheSameCube) {
    for (const char* name : {"cube_ascii.ply", "cube_binary.ply"}) {
        SCOPED_TRACE(name);
        const Model m = load(name);
        ASSERT_EQ(m.parts.size(), 1u);
        EXPECT_EQ(m.parts[0].mesh->positions.size(), 8u);
        EXPECT_EQ(m.parts[0].mesh->triangles.size(), 12u);
        EXPECT_TRUE(m.parts[0].mesh->normals.empty());  // flat
        expect_point(m.bounds.min, {0, 0, 0});
        expect_point(m.bounds.max, {1, 1, 1});
        ASSERT_EQ(m.materials.size(), 1u);
        EXPECT_EQ(m.materials[0].name, "default");
        EXPECT_EQ(m.materials[0].ks, Material{}.ks);  // PLY has no materials: glint's default
        // Outward winding: seen from +x, the face at x = 1 faces +x.
        const Ray ray{{3, 0.3f, 0.6f}, {-1, 0, 0}};
        const auto hit = intersect(m, ray);
        ASSERT_TRUE(hit);
        EXPECT_FLOAT_EQ(hit->first.t, 2);
        EXPECT_EQ(TriangleMesh{hit->second->mesh}.surface_at(ray, hit->first).normal,
                  (Normal3{1, 0, 0}));
    }
}

TEST(ModelLoader, StlAsciiAndBinaryGiveTheSameTetrahedron) {
    for (const char* name : {"tetra_ascii.stl", "tetra_binary.stl"}) {
        SCOPED_TRACE(name);
        const Model m = load(name);
        EXPECT_EQ(triangle_count(m), 4u);
        const Ray ray{{1, 1, 1}, normalize(Vector3{-1, -1, -1})};
        const auto hit = intersect(m, ray);
        ASSERT_TRUE(hit);
        // The slanted face x + y + z = 1 is met at (1/3, 1/3, 1/3): t = sqrt(3) (1 - 1/3).
        EXPECT_NEAR(hit->first.t, std::sqrt(3.0f) * 2 / 3, 1e-5f);
        const SurfacePoint sp = TriangleMesh{hit->second->mesh}.surface_at(ray, hit->first);
        EXPECT_NEAR(sp.normal.x, 1 / std::sqrt(3.0f), 1e-6f);
        EXPECT_NEAR(dot(sp.normal, sp.shading_normal), 1, 1e-5f);
    }
}

TEST(ModelLoader, ObjMaterialsMapAsDocumented) {
    const Model m = load("materials.obj");
    ASSERT_EQ(m.materials.size(), 3u);
    const auto find = [&](const std::string& name) {
        const auto it = std::find_if(m.materials.begin(), m.materials.end(),
                                     [&](const Material& x) { return x.name == name; });
        EXPECT_NE(it, m.materials.end()) << name;
        return it == m.materials.end() ? Material{} : *it;
    };
    const Material glass = find("glass");
    EXPECT_EQ(std::get<Color>(glass.color), Color::gray(0.5f));
    EXPECT_FLOAT_EQ(glass.kd, 1);
    EXPECT_FLOAT_EQ(glass.ka, 0.5f);  // Ka / Kd = 0.25 / 0.5
    EXPECT_FLOAT_EQ(glass.ks, 0.3f);
    EXPECT_FLOAT_EQ(glass.shininess, 50);
    EXPECT_FLOAT_EQ(glass.ior, 1.5f);
    EXPECT_NEAR(glass.transmit, 0.3f, 1e-6f);  // Tr 0.3
    EXPECT_FLOAT_EQ(glass.reflect, 0.3f);      // illum 3: reflect = Ks
    EXPECT_EQ(glass.emission, (Color{1, 0, 0}));
    const Material veil = find("veil");
    EXPECT_EQ(std::get<Color>(veil.color), (Color{0.2f, 0.4f, 0.6f}));
    EXPECT_EQ(veil.ka, 0);                     // no Ka
    EXPECT_NEAR(veil.transmit, 0.75f, 1e-6f);  // d 0.25
    EXPECT_EQ(veil.reflect, 0);                // illum 2
    EXPECT_EQ(veil.shininess, 1);              // no Ns
    const Material nowhere = find("nowhere");  // undefined: glint's default
    EXPECT_EQ(nowhere.ka, Material{}.ka);
    EXPECT_EQ(nowhere.kd, Material{}.kd);
    EXPECT_EQ(triangle_count(m), 3u);
    EXPECT_TRUE(has_warning(m, "1 degenerate triangle dropped")) << m.warnings.size();
    EXPECT_TRUE(has_warning(m, "materials.obj:12: usemtl \"nowhere\""));
}

TEST(ModelLoader, ObjWithTextureSpot) {
    const Model m = load("spot.obj");
    EXPECT_EQ(triangle_count(m), 5856u);
    ASSERT_EQ(m.materials.size(), 1u);
    const Material& spot = m.materials[0];
    EXPECT_EQ(spot.name, "spot");
    const auto* texture = std::get_if<ImageTexture>(&spot.color);
    ASSERT_TRUE(texture);
    EXPECT_EQ(texture->image->base().width, 1024);
    EXPECT_EQ(texture->scale, (Color{1, 1, 1}));
    EXPECT_FLOAT_EQ(spot.ka, 0.1f);
    EXPECT_FLOAT_EQ(spot.ks, 0.2f);
    EXPECT_FLOAT_EQ(spot.shininess, 40);
    ASSERT_EQ(m.parts.size(), 1u);
    EXPECT_FALSE(m.parts[0].mesh->uvs.empty());
    // The file's uvs lie in [0, 1]^2 but for a few that overshoot it (u down to -0.0522 and v up
    // to 1.00065, as its vt lines say); the repeat wrap covers those.
    for (const Point2 uv : m.parts[0].mesh->uvs) {
        ASSERT_TRUE(uv.x >= -0.0523f && uv.x <= 1 && uv.y >= 0 && uv.y <= 1.0007f)
            << uv.x << " " << uv.y;
    }
}

TEST(ModelLoader, FileNormalsKeptOrRecomputedWithACreaseAngle) {
    const Model with_file_normals = load("suzanne.obj");
    EXPECT_EQ(triangle_count(with_file_normals), 968u);
    ASSERT_EQ(with_file_normals.parts.size(), 1u);
    EXPECT_FALSE(with_file_normals.parts[0].mesh->normals.empty());

    ModelOptions flat;
    flat.crease_angle_degrees = 0;
    ModelOptions smooth;
    smooth.crease_angle_degrees = 180;
    const Model a = load("teapot_npm.obj", flat);
    const Model b = load("teapot_npm.obj", smooth);
    EXPECT_EQ(triangle_count(a), 992u);
    EXPECT_EQ(triangle_count(b), 992u);
    // Flat: every corner has its own face's normal, so vertices split to (nearly) one per
    // corner; smooth: one per position.
    EXPECT_GT(a.parts[0].mesh->positions.size(), 2 * b.parts[0].mesh->positions.size());
    EXPECT_LE(b.parts[0].mesh->positions.size(), 792u);
    const Model plain = load("teapot_npm.obj");
    EXPECT_TRUE(plain.parts[0].mesh->normals.empty());  // no normals in the file: flat
}

TEST(ModelLoader, ErrorsAreSceneErrorsNamingTheFile) {
    try {
        load_model(kMeshes / "no-such-file.obj");
        FAIL();
    } catch (const SceneError& e) {
        EXPECT_EQ(e.location().file, (kMeshes / "no-such-file.obj").string());
        EXPECT_EQ(e.message(), "mesh file not found");
    }
    try {
        load_model(kMeshes);
        FAIL();
    } catch (const SceneError& e) {
        EXPECT_NE(e.message().find("unknown mesh format"), std::string::npos);
    }
}

}  // namespace
}  // namespace glint::model_loader_test
