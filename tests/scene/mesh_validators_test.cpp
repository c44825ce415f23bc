// The OBJ and PLY validators on their own: accepted forms, located errors, and mutated files
// (truncated, bytes flipped) that must give a SceneError or pass, never crash.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include "glint/scene/mesh/obj_validator.h"
#include "glint/scene/mesh/ply_validator.h"
#include "glint/scene/mesh/text_lines.h"
#include "glint/scene/scene_error.h"

namespace glint {
namespace {

const std::filesystem::path kMeshes = std::filesystem::path(GLINT_SOURCE_DIR) / "tests/data/meshes";

std::string read(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

SceneError obj_error(const std::string& text) {
    try {
        validate_obj(kMeshes / "inline.obj", text);
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
    EXPECT_NO_THROW(validate_obj(kMeshes / "inline.obj", text));  // forward index 4 is fine
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
    const ObjCheck check = validate_obj(kMeshes / "materials.obj", read(kMeshes / "materials.obj"));
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

TEST(PlyValidator, NonPlyIsLeftToAssimp) {
    EXPECT_NO_THROW(validate_ply("x.ply", "solid ascii stl\n"));
    EXPECT_NO_THROW(validate_ply("x.ply", ""));
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
    survive_mutations(read(kMeshes / "materials.obj"),
                      [&](const std::string& t) { validate_obj(kMeshes / "materials.obj", t); });
}

}  // namespace
}  // namespace glint
