// The OBJ, PLY and ASCII STL validators on their own: accepted forms, located errors, and mutated
// files (truncated, bytes flipped) that must give a SceneError or pass, never crash.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include "glint/scene/mesh/glb_validator.h"
#include "glint/scene/mesh/gltf_validator.h"
#include "glint/scene/mesh/obj_validator.h"
#include "glint/scene/mesh/ply_validator.h"
#include "glint/scene/mesh/stl_validator.h"
#include "glint/scene/mesh/text_lines.h"
#include "glint/scene/scene_error.h"

namespace glint {
namespace {

const std::filesystem::path kMeshes = std::filesystem::path(GLINT_SOURCE_DIR) / "tests/data/meshes";
// The test meshes read only their own folder.
const ReadSandbox kSandbox = make_read_sandbox(kMeshes / "inline.obj");

std::string read(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

SceneError obj_error(const std::string& text) {
    try {
        validate_obj(kMeshes / "inline.obj", text, kSandbox);
    } catch (const SceneError& e) {
        return e;
    }
    ADD_FAILURE() << "no error for:\n" << text;
    return SceneError({}, "");
}

TEST(ObjValidator, AcceptsTheFormsAssimpReads) {
    const std::string text =
        "# comment\nv 0 0 0\nv 1 0 0 1\nv +0 1e0 -0.0 0.5 0.5 0.5\nvt 0\nvt 1 0\nvt 0 1 0\n"
        "vn 0 0 1\nf 1 2 3\nf 1/1 2/2 3/3\nf 1//1 2//1 3//1\nf -3/-3/-1 -2/-2/-1 -1/-1/-1\n"
        "f 1 2 3 1\ng group\ns 1\nl 1 2\np 1\r\nf 4 2 3\nv 0 0 1\n";
    EXPECT_NO_THROW(
        validate_obj(kMeshes / "inline.obj", text, kSandbox));  // forward index 4 is fine
}

TEST(ObjValidator, ErrorsPointAtTheToken) {
    SceneError e = obj_error("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2/7 3\n");
    EXPECT_EQ(e.location().line, 4);
    EXPECT_EQ(e.location().column, 7);
    EXPECT_EQ(e.message(), "face refers to texture coordinate 7, but the file has 0");
    EXPECT_EQ(e.source_line(), "f 1 2/7 3");
    EXPECT_EQ(e.span(), 1);

    e = obj_error("v 0 0\n");
    EXPECT_EQ(e.message(), "vertex needs 3 numbers, got 2");
    e = obj_error("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\nf 1/1/1/1 2 3\n");
    EXPECT_EQ(e.message(), "face corner \"1/1/1/1\" has more than 3 parts");
    e = obj_error("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x3\n");
    EXPECT_EQ(e.message(), "expected a vertex index, got \"x3\"");
    EXPECT_EQ(e.location().column, 7);
    e = obj_error("mtllib\n");
    EXPECT_EQ(e.message(), "mtllib names no file");
}

TEST(ObjValidator, FindsMaterialLibrariesAndUndefinedMaterials) {
    const ObjCheck check =
        validate_obj(kMeshes / "materials.obj", read(kMeshes / "materials.obj"), kSandbox);
    ASSERT_EQ(check.material_libraries.size(), 1u);
    EXPECT_EQ(check.material_libraries[0].filename(), "materials.mtl");
    ASSERT_EQ(check.undefined_materials.size(), 1u);
    EXPECT_EQ(check.undefined_materials[0], "nowhere");
    EXPECT_EQ(check.warnings.size(), 1u);
}

TEST(PlyValidator, GoodFilesPass) {
    for (const char* name : {"cube_ascii.ply", "cube_binary.ply"}) {
        EXPECT_NO_THROW(validate_ply(kMeshes / name, read(kMeshes / name))) << name;
    }
}

// Assimp also reads files with "ply" after blank lines or NULs, or in another case, and hung or
// leaked on some (found by fuzzing): a .ply file must start with the line "ply", in any case.
TEST(PlyValidator, FileNotStartingWithPlyIsRefusedAtItsStart) {
    for (const std::string& text : {std::string("solid ascii stl\n"), std::string(),
                                    std::string("\nply\nformat ascii 1.0\nend_header\n"),
                                    std::string("\0\0ply\n", 6), std::string("plyx\n")}) {
        try {
            validate_ply("x.ply", text);
            ADD_FAILURE() << "accepted: " << text;
        } catch (const SceneError& e) {
            EXPECT_EQ(e.message(), "a PLY file must start with a line \"ply\"");
            EXPECT_EQ(e.location().line, 1);
            EXPECT_EQ(e.location().column, 1);
        }
    }
    EXPECT_NO_THROW(validate_ply("x.ply", "PLY\nformat ascii 1.0\nend_header\n"));
}

SceneError stl_error(const std::string& text) {
    try {
        validate_stl(kMeshes / "inline.stl", text);
    } catch (const SceneError& e) {
        return e;
    }
    ADD_FAILURE() << "no error for:\n" << text;
    return SceneError({}, "");
}

const std::string kFacet =
    " facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 1 0 0\n   vertex 0 1 0\n"
    "  endloop\n endfacet\n";

TEST(StlValidator, AcceptsTheFormsAssimpReads) {
    for (const char* name : {"tetra_ascii.stl", "tetra_binary.stl"}) {
        EXPECT_NO_THROW(validate_stl(kMeshes / name, read(kMeshes / name))) << name;
    }
    // Two solids, CRLF, tabs, blank lines, names with spaces, +signs and exponents; a file
    // whose last solid lacks endsolid.
    std::string text = "\n  solid first part\r\n" + kFacet + "endsolid first part\r\n\n";
    text += "solid\n\tfacet normal +0 -0 1e0\n outer\tloop\nvertex 1e-3 0 0\nvertex 1 0 0\n";
    text += "vertex 0 1.5E+0 0\nendloop\nendfacet\n" + kFacet;
    EXPECT_NO_THROW(validate_stl(kMeshes / "inline.stl", text));
    // Not ASCII STL: left to Assimp.
    EXPECT_NO_THROW(validate_stl("x.stl", "not an stl file"));
    std::string binary(84 + 50, '\0');
    binary.replace(0, 5, "solid");
    binary[80] = 1;
    EXPECT_NO_THROW(validate_stl("x.stl", binary));
}

TEST(StlValidator, ErrorsPointAtTheToken) {
    SceneError e = stl_error("solid x\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 inf\n");
    EXPECT_EQ(e.location().line, 4);
    EXPECT_EQ(e.location().column, 15);
    EXPECT_EQ(e.message(), "vertex has a coordinate that is not finite: \"inf\"");
    EXPECT_EQ(e.source_line(), "   vertex 0 0 inf");
    EXPECT_EQ(e.span(), 3);

    e = stl_error("solid x\n facet normal 0 0\n");
    EXPECT_EQ(e.message(), "facet normal needs 3 numbers, got 2");
    e = stl_error("solid x\n facet 0 0 1\n");
    EXPECT_EQ(e.message(), "expected \"normal\", got \"0\"");
    e = stl_error("solid x\n facet normal 0 0 1\n  vertex 0 0 0\n");
    EXPECT_EQ(e.message(), "expected \"outer loop\", got \"vertex\"");
    EXPECT_EQ(e.location().line, 3);
    e = stl_error("solid x\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0 1\n");
    EXPECT_EQ(e.message(), "unexpected \"1\" after \"0\"");
    EXPECT_EQ(e.location().column, 17);
    e = stl_error("solid x\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n  endloop\n");
    EXPECT_EQ(e.message(), "the facet has 1 vertices; STL facets are triangles");
    e = stl_error("solid x\n" + kFacet + " endfacet\n");
    EXPECT_EQ(e.message(), "expected \"facet\" or \"endsolid\", got \"endfacet\"");
    EXPECT_EQ(e.location().line, 9);
    e = stl_error("solid x\n" + kFacet + "endsolid x\nfacet normal 0 0 1\n");
    EXPECT_EQ(e.message(), "expected \"solid\", got \"facet\"");
    // A binary STL whose length does not match its count, with a header that starts "solid".
    e = stl_error("solid header\n\x01\x02\x03 garbage\n");
    EXPECT_NE(e.notes().at(0).find("binary STL"), std::string::npos);
}

SceneError gltf_error(const std::string& json) {
    try {
        validate_gltf_json("inline.gltf", json, false);
    } catch (const SceneError& e) {
        return e;
    }
    ADD_FAILURE() << "no error for:\n" << json;
    return SceneError({}, "");
}

TEST(GltfValidator, DataUrisHoldBase64Only) {
    // Base64, with a JSON-escaped slash; a data URI that is not base64; a file's name.
    for (const char* uri : {"data:application/octet-stream;base64,AAAA+/9=",
                            "data:application/octet-stream;base64,AA\\/A",
                            "data:text/plain,not base64 at all!", "model.bin", "data:;base64,"}) {
        EXPECT_NO_THROW(validate_gltf_json(
            "inline.gltf", std::string("{\"buffers\": [{\"uri\": \"") + uri + "\"}]}", false))
            << uri;
    }
    SceneError e = gltf_error("{\n \"buffers\": [{\"uri\": \"data:;base64,AAA\xc3\xa9\"}]\n}");
    EXPECT_EQ(e.location().line, 2);
    EXPECT_EQ(e.location().column, 39);
    EXPECT_EQ(e.message(),
              "a base64 data URI holds the byte 0xc3 at its character 17, which is not base64 "
              "(A-Z, a-z, 0-9, +, / and =)");
    e = gltf_error("{\"images\": [{\"uri\": \"data:image/png;base64,AA*A\"}]}");
    EXPECT_EQ(e.message(),
              "a base64 data URI holds '*' at its character 25, which is not base64 (A-Z, a-z, "
              "0-9, +, / and =)");
    // A .glb file has no lines: the error names the file alone.
    try {
        validate_gltf_json("model.glb", "{\"uri\": \"data:;base64,\x80\"}", true);
        ADD_FAILURE() << "no error";
    } catch (const SceneError& glb) {
        EXPECT_EQ(glb.location().line, 0);
    }
}

TEST(GltfValidator, IndicesAreUnsignedIntegerScalars) {
    const auto gltf = [](const std::string& indices, const std::string& accessor) {
        return "{\"meshes\": [{\"primitives\": [{\"attributes\": {\"POSITION\": 0}, " + indices +
               "}]}],\n \"accessors\": [{\"type\": \"VEC3\", \"componentType\": 5126}, " +
               accessor + "]}";
    };
    for (const char* component : {"5121", "5123", "5125"}) {
        EXPECT_NO_THROW(validate_gltf_json(
            "inline.gltf",
            gltf("\"indices\": 1", std::string("{\"componentType\": ") + component +
                                       ", \"count\": 3, \"type\": \"SCALAR\"}"),
            false));
    }
    // A sparse accessor's indices are an object; an accessor that is not there is Assimp's to
    // report.
    EXPECT_NO_THROW(validate_gltf_json(
        "inline.gltf",
        gltf("\"indices\": 5", "{\"sparse\": {\"indices\": {\"componentType\": 5126}}}"), false));
    SceneError e =
        gltf_error(gltf("\"indices\": 1", "{\"type\": \"VEC2\", \"componentType\": 5126}"));
    EXPECT_EQ(e.location().line, 1);
    EXPECT_EQ(e.location().column, 72);
    EXPECT_EQ(e.message(),
              "a mesh primitive's indices are accessor 1, of type \"VEC2\" and componentType 5126; "
              "glTF indices are SCALAR unsigned integers (componentType 5121, 5123 or 5125)");
    e = gltf_error(gltf("\"indices\": 1", "{\"type\": \"SCALAR\"}"));
    EXPECT_NE(e.message().find("componentType (none)"), std::string::npos) << e.message();
    // Nesting far deeper than any stack could recurse through is walked, not recursed.
    const std::string deep = std::string(200000, '[') + std::string(200000, ']');
    EXPECT_NO_THROW(validate_gltf_json("inline.gltf",
                                       "{\"accessors\": [" + deep + "], \"indices\": 1}", false));
}

TEST(GlbValidator, HeaderAndChunksMustFitTheFile) {
    const auto glb = [](std::uint32_t length, std::uint32_t chunk) {
        std::string bytes = "glTF";
        for (const std::uint32_t v : {2u, length, chunk, 0x4e4f534au})
            for (int i = 0; i < 4; ++i) bytes += char(v >> (8 * i));
        return bytes + "{} ";
    };
    EXPECT_NO_THROW(validate_glb("x.glb", glb(23, 3)));
    const auto message = [&](const std::string& bytes) {
        try {
            validate_glb("x.glb", bytes);
        } catch (const SceneError& e) {
            return e.message();
        }
        return std::string("(no error)");
    };
    // A length too short for a chunk: Assimp reads the chunk's header all the same.
    EXPECT_EQ(message(glb(15, 0xee000000)),
              "the GLB header gives a length of 15 bytes, too short for the 12-byte header and a "
              "chunk (at least 20)");
    EXPECT_EQ(message(glb(23, 4)),
              "the GLB chunk at byte 12 claims 4 bytes, past the end of the file's 23");
    EXPECT_EQ(message(glb(24, 3)),
              "the GLB header gives a length of 24 bytes, but the file has 23 (it is truncated)");
}

TEST(TextLines, LinesEndWhereTheirReaderEndsThem) {
    using namespace std::string_view_literals;
    const auto lines_of = [](std::string_view text, LineBreaks breaks) {
        const TextLines lines(text, "t", breaks);
        std::vector<std::string> out;
        for (std::size_t i = 0; i < lines.size(); ++i) out.emplace_back(lines.line(i));
        return out;
    };
    using Lines = std::vector<std::string>;
    const std::string_view text = "a\r\nb\rc\fd\0e\nf"sv;
    EXPECT_EQ(lines_of(text, LineBreaks::newline), (Lines{"a", std::string("b\rc\fd\0e", 7), "f"}));
    EXPECT_EQ(lines_of(text, LineBreaks::obj), (Lines{"a", "b", "c", "d", "e", "f"}));
    EXPECT_EQ(lines_of("x\r\n\r\ny\r", LineBreaks::obj), (Lines{"x", "", "y"}));
    EXPECT_EQ(lines_of("x\r", LineBreaks::newline), (Lines{"x"}));
    EXPECT_EQ(lines_of("", LineBreaks::obj), Lines{});
}

TEST(TextLines, NumbersParseWholeTokensOnly) {
    EXPECT_EQ(parse_float("1.5"), 1.5f);
    EXPECT_EQ(parse_float("+2"), 2.0f);
    EXPECT_FALSE(parse_float("1.5x"));
    EXPECT_FALSE(parse_float(""));
    EXPECT_TRUE(std::isinf(*parse_float("-1e99")));
    EXPECT_TRUE(std::isnan(*parse_float("nan")));
    EXPECT_EQ(parse_integer("-12"), -12);
    EXPECT_FALSE(parse_integer("1.0"));
    EXPECT_FALSE(parse_integer("99999999999999999999999"));
}

// Mutations of good files: every outcome but a crash, a hang or a foreign exception is fine.
template <typename Validate>
void survive_mutations(const std::string& original, Validate validate) {
    std::mt19937 rng(17);
    for (int i = 0; i < 300; ++i) {
        std::string text = original;
        const int kind = i % 3;
        if (kind == 0) text.resize(rng() % (text.size() + 1));  // truncated
        if (kind >= 1) {
            for (int k = 0; k < 1 + i % 8; ++k) {
                const char bytes[] = {'\0', '\n', ' ', '-', '/', '9', 'e', char(0xff), '#'};
                text[rng() % text.size()] = bytes[rng() % sizeof bytes];
            }
        }
        try {
            validate(text);
        } catch (const SceneError&) {
        } catch (const std::exception& e) {
            FAIL() << "mutation " << i << " threw " << e.what();
        }
    }
}

TEST(MeshValidators, SurviveMutatedFiles) {
    for (const char* name : {"cube_ascii.ply", "cube_binary.ply"}) {
        survive_mutations(read(kMeshes / name),
                          [&](const std::string& t) { validate_ply(kMeshes / name, t); });
    }
    survive_mutations(read(kMeshes / "materials.obj"), [&](const std::string& t) {
        validate_obj(kMeshes / "materials.obj", t, kSandbox);
    });
    survive_mutations(read(kMeshes / "tetra_ascii.stl"),
                      [&](const std::string& t) { validate_stl(kMeshes / "tetra_ascii.stl", t); });
}

}  // namespace
}  // namespace glint
