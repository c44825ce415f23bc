// The sandbox at work in the loaders: textures, meshes, OBJ material libraries and their
// textures, and glTF buffers that lead outside the scene's folder (by "..", an absolute path or a
// symbolic link) are refused with the path and where the scene names it, and load once their
// folder is allowed; paths that stay inside load as before.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "glint/image/image.h"
#include "glint/image/png_io.h"
#include "glint/scene/load_scene.h"
#include "glint/scene/scene_error.h"

namespace glint {
namespace {

namespace fs = std::filesystem;

const fs::path kMeshes = fs::path(GLINT_SOURCE_DIR) / "tests/data/meshes";

void write_text(const fs::path& file, const std::string& text) {
    std::ofstream(file, std::ios::binary) << text;
}

std::string read_text(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

bool any_note_contains(const SceneError& e, const std::string& text) {
    return std::any_of(e.notes().begin(), e.notes().end(),
                       [&](const std::string& n) { return n.find(text) != std::string::npos; });
}

// The error loading `file` gives; fails the test when it loads.
SceneError load_error(const fs::path& file, const LoadOptions& options = {}) {
    try {
        load_scene(file, options);
    } catch (const SceneError& e) {
        return e;
    }
    ADD_FAILURE() << file << " loaded, but the sandbox should refuse it";
    return SceneError({}, "");
}

// Loads `file`, failing the test (with the message) when it does not load.
void expect_loads(const fs::path& file, const LoadOptions& options = {}) {
    try {
        load_scene(file, options);
    } catch (const SceneError& e) {
        ADD_FAILURE() << format_scene_error(e);
    }
}

// <dir>/scene/ holds the scenes and sub/ with a texture and a mesh; <dir>/outside/ holds the same
// files, out of the scenes' reach; so does <dir>/out/, whose name is a prefix of "outside".
class SceneSandbox : public ::testing::Test {
protected:
    void SetUp() override {
        const fs::path dir = fs::path(GLINT_TEST_OUTPUT_DIR) / "scene_sandbox" /
                             ::testing::UnitTest::GetInstance()->current_test_info()->name();
        fs::remove_all(dir);
        fs::create_directories(dir);
        dir_ = fs::canonical(dir);
        scene_ = dir_ / "scene";
        outside_ = dir_ / "outside";
        for (const fs::path& folder : {scene_ / "sub", outside_, dir_ / "out"}) {
            fs::create_directories(folder);
            Image image(2, 2);
            image.pixels = {Color::gray(1), Color::gray(0), Color::gray(0), Color::gray(1)};
            write_png(folder / "tex.png", image);
            fs::copy_file(kMeshes / "tetra_ascii.stl", folder / "mesh.stl");
        }
    }

    // A scene in scene/ whose sphere has an image texture at `texture`, the file key on line 3 at
    // column 34.
    fs::path texture_scene(const std::string& texture) const {
        write_text(scene_ / "s.yaml",
                   "camera: {from: [0, 0, -5], at: [0, 0, 0]}\n"
                   "materials:\n"
                   "  a: {color: {type: image, file: \"" +
                       texture +
                       "\"}}\n"
                       "objects: [{type: sphere, center: [0, 0, 0], radius: 1, material: a}]\n");
        return scene_ / "s.yaml";
    }

    // A scene in scene/ with a mesh object from `mesh`, the file key on line 3 at column 24.
    fs::path mesh_scene(const std::string& mesh) const {
        write_text(scene_ / "m.yaml",
                   "camera: {from: [0, 0, -5], at: [0, 0, 0]}\n"
                   "objects:\n"
                   "  - {type: mesh, file: \"" +
                       mesh + "\"}\n");
        return scene_ / "m.yaml";
    }

    LoadOptions allowing_outside() const { return {{outside_}}; }

    // Checks the refusal of `written` in a scene: at the YAML value, naming the path as written
    // and where it leads.
    void expect_refused(const fs::path& scene, const std::string& what, const std::string& written,
                        const fs::path& leads_to, int column) const {
        SCOPED_TRACE(written);
        const SceneError e = load_error(scene);
        EXPECT_EQ(e.location().file, scene.string());
        EXPECT_EQ(e.location().line, 3);
        EXPECT_EQ(e.location().column, column);
        EXPECT_EQ(e.message(),
                  what + " \"" + written + "\" is outside the folders the scene may read");
        EXPECT_TRUE(any_note_contains(e, "it resolves to " + leads_to.string()))
            << format_scene_error(e);
        EXPECT_TRUE(any_note_contains(e, "allow the folder with --allow-read DIR"));
        EXPECT_FALSE(e.source_line().empty());
    }

    fs::path dir_, scene_, outside_;
};

TEST_F(SceneSandbox, TexturesLeadingOutAreRefusedAtTheirKey) {
    const std::string absolute = (outside_ / "tex.png").string();
    fs::create_symlink("../outside/tex.png", scene_ / "link.png");
    fs::create_directory_symlink("../outside", scene_ / "linked-folder");
    for (const std::string& path :
         {std::string("../outside/tex.png"), std::string("sub/../../outside/tex.png"), absolute,
          std::string("link.png"), std::string("linked-folder/tex.png")}) {
        expect_refused(texture_scene(path), "texture", path, outside_ / "tex.png", 34);
        expect_loads(texture_scene(path), allowing_outside());
    }
}

TEST_F(SceneSandbox, MeshesLeadingOutAreRefusedAtTheirKey) {
    const std::string absolute = (outside_ / "mesh.stl").string();
    fs::create_symlink("../outside/mesh.stl", scene_ / "link.stl");
    for (const std::string& path :
         {std::string("../outside/mesh.stl"), absolute, std::string("link.stl")}) {
        expect_refused(mesh_scene(path), "mesh file", path, outside_ / "mesh.stl", 24);
        expect_loads(mesh_scene(path), allowing_outside());
    }
}

TEST_F(SceneSandbox, ASceneInASubfolderEscapesByDotDot) {
    // ../.. from scene/sub/ leads to <dir>: out of scene/sub, the folder of this scene.
    write_text(scene_ / "sub" / "deep.yaml",
               "camera: {from: [0, 0, -5], at: [0, 0, 0]}\n"
               "objects:\n"
               "  - {type: mesh, file: ../../outside/mesh.stl}\n");
    const SceneError e = load_error(scene_ / "sub" / "deep.yaml");
    EXPECT_EQ(e.location().line, 3);
    EXPECT_EQ(e.location().column, 24);
    EXPECT_EQ(e.message(),
              "mesh file \"../../outside/mesh.stl\" is outside the folders the scene may read");
}

TEST_F(SceneSandbox, PathsThatStayInsideLoad) {
    fs::create_symlink("sub/tex.png", scene_ / "inside-link.png");
    for (const std::string& path :
         {std::string("sub/tex.png"), std::string("./sub/../sub/tex.png"),
          std::string("inside-link.png"), (scene_ / "sub" / "tex.png").string()}) {
        SCOPED_TRACE(path);
        expect_loads(texture_scene(path));
    }
    expect_loads(mesh_scene("./sub/mesh.stl"));
    expect_loads(mesh_scene("sub/../sub/mesh.stl"));
}

TEST_F(SceneSandbox, AFileOutsideIsRefusedWhetherOrNotItExists) {
    // The refusal comes before any look at the file, so it tells nothing about what is there.
    const SceneError e = load_error(texture_scene("../outside/no-such.png"));
    EXPECT_EQ(e.message(),
              "texture \"../outside/no-such.png\" is outside the folders the scene may read");
}

TEST_F(SceneSandbox, AllowingAFolderWhoseNameIsAPrefixAllowsNothingElse) {
    const LoadOptions allow_out{{dir_ / "out"}};
    const SceneError e = load_error(texture_scene("../outside/tex.png"), allow_out);
    EXPECT_EQ(e.message(),
              "texture \"../outside/tex.png\" is outside the folders the scene may read");
    expect_loads(texture_scene("../out/tex.png"), allow_out);
}

TEST_F(SceneSandbox, SeveralFoldersMayBeAllowed) {
    write_text(scene_ / "two.yaml",
               "camera: {from: [0, 0, -5], at: [0, 0, 0]}\n"
               "objects:\n"
               "  - {type: mesh, file: ../outside/mesh.stl}\n"
               "  - {type: mesh, file: ../out/mesh.stl}\n");
    load_error(scene_ / "two.yaml", allowing_outside());
    expect_loads(scene_ / "two.yaml", LoadOptions{{outside_, dir_ / "out"}});
}

TEST_F(SceneSandbox, AnObjMaterialLibraryLeadingOutIsRefusedAtItsLine) {
    write_text(outside_ / "lib.mtl", "newmtl m\nKd 1 0 0\n");
    write_text(scene_ / "a.obj",
               "v 0 0 0\nv 1 0 0\nv 0 1 0\nmtllib ../outside/lib.mtl\nusemtl m\nf 1 2 3\n");
    for (const fs::path& file : {scene_ / "a.obj", mesh_scene("a.obj")}) {
        SCOPED_TRACE(file);
        const SceneError e = load_error(file);
        EXPECT_EQ(e.location().file, (scene_ / "a.obj").string());
        EXPECT_EQ(e.location().line, 4);
        EXPECT_EQ(e.location().column, 8);
        EXPECT_EQ(e.message(),
                  "material library \"../outside/lib.mtl\" is outside the folders "
                  "the scene may read");
        EXPECT_TRUE(any_note_contains(e, (outside_ / "lib.mtl").string()));
        expect_loads(file, allowing_outside());
    }
}

TEST_F(SceneSandbox, AnMtlTextureLeadingOutIsRefusedAtItsLine) {
    write_text(scene_ / "b.mtl", "newmtl m\nKd 1 1 1\nmap_Kd ../outside/tex.png\n");
    write_text(scene_ / "b.obj",
               "mtllib b.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nusemtl m\nf 1/1 2/1 3/1\n");
    const SceneError e = load_error(scene_ / "b.obj");
    EXPECT_EQ(e.location().file, (scene_ / "b.mtl").string());
    EXPECT_EQ(e.location().line, 3);
    EXPECT_EQ(e.location().column, 8);
    EXPECT_EQ(e.message(),
              "texture file \"../outside/tex.png\" is outside the folders the scene may read");
    expect_loads(scene_ / "b.obj", allowing_outside());
}

// Assimp opens a glTF file's buffers itself, through glint's sandboxed file access.
TEST_F(SceneSandbox, AGltfBufferLeadingOutIsRefusedNamingTheGltfFile) {
    const std::string gltf = read_text(kMeshes / "quad.gltf");
    const std::string uri = "\"uri\": \"quad.bin\"";
    ASSERT_NE(gltf.find(uri), std::string::npos);
    fs::copy_file(kMeshes / "quad.bin", dir_ / "outside.bin");
    std::string escaping = gltf;
    escaping.replace(escaping.find(uri), uri.size(), "\"uri\": \"../outside.bin\"");
    write_text(scene_ / "escaping.gltf", escaping);
    for (const fs::path& file : {scene_ / "escaping.gltf", mesh_scene("escaping.gltf")}) {
        SCOPED_TRACE(file);
        const SceneError e = load_error(file);
        EXPECT_EQ(e.location().file, (scene_ / "escaping.gltf").string());
        EXPECT_EQ(e.location().line, 0);
        EXPECT_NE(e.message().find("../outside.bin\" is outside the folders the scene may read"),
                  std::string::npos)
            << format_scene_error(e);
        EXPECT_TRUE(any_note_contains(e, "it resolves to " + (dir_ / "outside.bin").string()));
        expect_loads(file, LoadOptions{{dir_}});
    }
}

// Assimp 5.2 takes an absolute buffer URI as relative to the glTF file's folder, so it never
// leads out: the file is not found there, and is never read where the URI points.
TEST_F(SceneSandbox, AGltfBufferWithAnAbsoluteUriIsNotRead) {
    const std::string gltf = read_text(kMeshes / "quad.gltf");
    const std::string uri = "\"uri\": \"quad.bin\"";
    fs::copy_file(kMeshes / "quad.bin", dir_ / "outside.bin");
    std::string absolute = gltf;
    absolute.replace(absolute.find(uri), uri.size(),
                     "\"uri\": \"" + (dir_ / "outside.bin").string() + "\"");
    write_text(scene_ / "absolute.gltf", absolute);
    for (const LoadOptions& options : {LoadOptions{}, LoadOptions{{dir_}}}) {
        const SceneError e = load_error(scene_ / "absolute.gltf", options);
        EXPECT_EQ(e.location().file, (scene_ / "absolute.gltf").string());
        EXPECT_NE(e.message().find("outside.bin"), std::string::npos) << format_scene_error(e);
    }
}

// glint loads a glTF file's images itself, looked for beside the file.
TEST_F(SceneSandbox, AGltfImageLeadingOutIsRefusedNamingTheGltfFile) {
    std::string gltf = read_text(kMeshes / "quad.gltf");
    const std::string pbr = "\"pbrMetallicRoughness\": {", materials = "\"materials\": [";
    ASSERT_NE(gltf.find(pbr), std::string::npos);
    ASSERT_NE(gltf.find(materials), std::string::npos);
    gltf.replace(gltf.find(pbr), pbr.size(), pbr + "\"baseColorTexture\": {\"index\": 0},");
    fs::copy_file(kMeshes / "quad.bin", scene_ / "quad.bin");
    const auto textured = [&](const std::string& image) {
        std::string text = gltf;
        text.replace(text.find(materials), materials.size(),
                     "\"images\": [{\"uri\": \"" + image +
                         "\"}], \"textures\": [{\"source\": 0}], " + materials);
        write_text(scene_ / "textured.gltf", text);
        return scene_ / "textured.gltf";
    };
    expect_loads(textured("sub/tex.png"));
    const SceneError e = load_error(textured("../outside/tex.png"));
    EXPECT_EQ(e.location().file, (scene_ / "textured.gltf").string());
    EXPECT_EQ(e.message(),
              "texture file \"../outside/tex.png\" is outside the folders the scene may read")
        << format_scene_error(e);
    EXPECT_TRUE(any_note_contains(e, "it resolves to " + (outside_ / "tex.png").string()));
    expect_loads(textured("../outside/tex.png"), allowing_outside());
}

TEST_F(SceneSandbox, AModelFileRenderedOnItsOwnReadsOnlyItsFolder) {
    fs::copy_file(kMeshes / "spot.obj", scene_ / "spot.obj");
    fs::copy_file(kMeshes / "spot.mtl", scene_ / "spot.mtl");
    fs::copy_file(kMeshes / "spot_texture.png", scene_ / "spot_texture.png");
    expect_loads(scene_ / "spot.obj");
    // A model file named by a symbolic link is read where the link leads; what it names is
    // looked for beside the link, inside the link's folder.
    fs::create_symlink(outside_ / "mesh.stl", scene_ / "linked.stl");
    expect_loads(scene_ / "linked.stl");
}

// What a resume file checks for changes: every file the scene read besides its own, each once,
// whoever opened it (glint's texture loader, Assimp for meshes, material libraries and buffers).
TEST_F(SceneSandbox, TheFilesASceneReadAreListedOnceEach) {
    write_text(scene_ / "b.mtl", "newmtl m\nKd 1 1 1\nmap_Kd sub/tex.png\n");
    write_text(scene_ / "b.obj",
               "mtllib b.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nusemtl m\nf 1/1 2/1 3/1\n");
    write_text(scene_ / "all.yaml",
               "camera: {from: [0, 0, -5], at: [0, 0, 0]}\n"
               "materials:\n"
               "  a: {color: {type: image, file: sub/tex.png}}\n"
               "  b: {color: {type: image, file: ../outside/tex.png}}\n"
               "objects:\n"
               "  - {type: sphere, center: [0, 0, 0], radius: 1, material: a}\n"
               "  - {type: sphere, center: [2, 0, 0], radius: 1, material: b}\n"
               "  - {type: mesh, file: b.obj}\n"
               "  - {type: mesh, file: sub/mesh.stl}\n"
               "  - {type: mesh, file: sub/mesh.stl}\n");
    const Scene scene = load_scene(scene_ / "all.yaml", allowing_outside());
    const std::vector<fs::path> expected = {scene_ / "sub/tex.png", outside_ / "tex.png",
                                            scene_ / "b.obj", scene_ / "b.mtl",
                                            scene_ / "sub/mesh.stl"};
    EXPECT_EQ(scene.sources.files_read, expected);

    // A model file on its own lists what it read, not itself; an NFF file reads nothing else.
    const Scene model = load_scene(scene_ / "b.obj");
    EXPECT_EQ(model.sources.files_read,
              (std::vector<fs::path>{scene_ / "b.mtl", scene_ / "sub/tex.png"}));
    write_text(scene_ / "s.nff",
               "v\nfrom 0 0 -5\nat 0 0 0\nup 0 1 0\nangle 40\nhither 1\n"
               "resolution 8 8\nf 1 1 1 1 0 0 0 1\ns 0 0 0 1\n");
    EXPECT_TRUE(load_scene(scene_ / "s.nff").sources.files_read.empty());
}

// A pipe would block the open and a device like /dev/zero never end: only regular files are read.
TEST_F(SceneSandbox, APipeOrAFolderInPlaceOfAFileIsRefusedAtItsKey) {
    ASSERT_EQ(::mkfifo((scene_ / "pipe.png").c_str(), 0600), 0);
    fs::create_directories(scene_ / "folder.png");
    for (const std::string& path : {std::string("pipe.png"), std::string("folder.png")}) {
        SCOPED_TRACE(path);
        const SceneError e = load_error(texture_scene(path));
        EXPECT_EQ(e.location().line, 3);
        EXPECT_EQ(e.location().column, 34);
        EXPECT_EQ(e.message(), "texture \"" + path + "\" is not a regular file");
    }
    ASSERT_EQ(::mkfifo((scene_ / "pipe.stl").c_str(), 0600), 0);
    const SceneError e = load_error(mesh_scene("pipe.stl"));
    EXPECT_EQ(e.message(), "mesh file \"pipe.stl\" is not a regular file") << format_scene_error(e);
    // The sandbox allows /dev here, but a device is still no texture.
    const SceneError device = load_error(texture_scene("/dev/zero"), LoadOptions{{"/dev"}});
    EXPECT_EQ(device.message(), "texture \"/dev/zero\" is not a regular file");
}

}  // namespace
}  // namespace glint
