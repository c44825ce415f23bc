// The NFF parser: the SPD's jacks read value by value, the syntax the SPD and the spec both use,
// the malformed files in tests/scene/bad_nff/, and mangled input that must give SceneErrors only.
#include "glint/scene/nff/nff_parser.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "bad_file_checks.h"
#include "glint/scene/nff/nff_to_scene.h"

namespace glint::nff_parser_test {
namespace {

const std::filesystem::path kSource(GLINT_SOURCE_DIR);
const std::filesystem::path kJacks = kSource / "tests/data/spd/jacks.nff";

// Every value of a scene, floats in hexadecimal, so that two scenes compare exactly.
std::string dump(const NffScene& scene) {
    std::ostringstream out;
    out << std::hexfloat;
    const auto p3 = [&](auto p) { out << p.x << ' ' << p.y << ' ' << p.z << ' '; };
    if (scene.view) {
        const NffView& v = *scene.view;
        out << "v ";
        p3(v.from), p3(v.at), p3(v.up);
        out << v.angle_degrees << ' ' << v.hither << ' ' << v.width << ' ' << v.height << '\n';
    }
    if (const auto& b = scene.background) out << "b " << b->r << ' ' << b->g << ' ' << b->b << '\n';
    for (const NffLight& l : scene.lights) {
        out << "l ";
        p3(l.position);
        if (l.color) out << l.color->r << ' ' << l.color->g << ' ' << l.color->b;
        out << '\n';
    }
    for (const NffMaterial& m : scene.materials) {
        out << "f " << m.color.r << ' ' << m.color.g << ' ' << m.color.b << ' ' << m.kd << ' '
            << m.ks << ' ' << m.shine << ' ' << m.transmittance << ' ' << m.ior << '\n';
    }
    for (const NffObject& o : scene.objects) {
        out << o.material << ' ';
        if (const auto* s = std::get_if<NffSphere>(&o.primitive)) {
            out << "s ";
            p3(s->center);
            out << s->radius;
        } else if (const auto* c = std::get_if<NffCone>(&o.primitive)) {
            out << "c ";
            p3(c->base);
            out << c->base_radius << ' ';
            p3(c->apex);
            out << c->apex_radius;
        } else if (const auto* p = std::get_if<NffPolygon>(&o.primitive)) {
            out << "p ";
            for (const Point3& v : p->vertices) p3(v);
        } else if (const auto* pp = std::get_if<NffPatch>(&o.primitive)) {
            out << "pp ";
            for (std::size_t i = 0; i < pp->vertices.size(); ++i)
                p3(pp->vertices[i]), p3(pp->normals[i]);
        }
        out << '\n';
    }
    return out.str();
}

const char* const kView =
    "v\nfrom 0 0 -8\nat 0 0 0\nup 0 1 0\nangle 25\nhither 0.001\nresolution 256 256\n";

TEST(NffParser, JacksGivesItsExactValues) {
    const NffScene scene = load_nff(kJacks);
    EXPECT_EQ(scene.file_name, kJacks.string());
    ASSERT_TRUE(scene.background);
    EXPECT_EQ(*scene.background, (Color{0.2f, 0.05f, 0.2f}));
    ASSERT_TRUE(scene.view);
    const NffView& v = require_view(scene);
    EXPECT_EQ(v.from, (Point3{0, 0, -8}));
    EXPECT_EQ(v.at, (Point3{0, 0, 0}));
    EXPECT_EQ(v.up, (Vector3{0, 1, 0}));
    EXPECT_EQ(v.angle_degrees, 25);
    EXPECT_EQ(v.hither, 0.001f);
    EXPECT_EQ(v.width, 256);
    EXPECT_EQ(v.height, 256);
    EXPECT_EQ(v.location.line, 2u);  // `b` comes first, as the SPD writes it
    EXPECT_EQ(v.location.column, 1u);

    ASSERT_EQ(scene.lights.size(), 1u);
    EXPECT_EQ(scene.lights[0].position, (Point3{-10, 3, -20}));
    EXPECT_FALSE(scene.lights[0].color);
    ASSERT_EQ(scene.materials.size(), 1u);
    const NffMaterial& m = scene.materials[0];
    EXPECT_EQ(m.color, (Color{0.737f, 0.561f, 0.561f}));
    EXPECT_EQ(m.kd, 0.7f);
    EXPECT_EQ(m.ks, 0.7f);
    EXPECT_EQ(m.shine, 11.1434f);
    EXPECT_EQ(m.transmittance, 0);
    EXPECT_EQ(m.ior, 1);
    EXPECT_EQ(m.location.line, 10u);

    ASSERT_EQ(scene.objects.size(), 9u);
    const auto& c0 = std::get<NffCone>(scene.objects[0].primitive);
    EXPECT_EQ(c0.base, (Point3{-0.704769f, -0.128258f, -0.222149f}));
    EXPECT_EQ(c0.base_radius, 0.075f);
    EXPECT_EQ(c0.apex, (Point3{0.704769f, 0.128258f, 0.222149f}));
    EXPECT_EQ(c0.apex_radius, 0.075f);
    const auto& c2 = std::get<NffCone>(scene.objects[2].primitive);
    EXPECT_EQ(c2.base, (Point3{0.256515f, -0.352385f, -0.610348f}));
    EXPECT_EQ(c2.apex, (Point3{-0.256515f, 0.352385f, 0.610348f}));
    const Point3 centers[6] = {{0.704769f, 0.128258f, 0.222149f},
                               {0, 0.649519f, -0.375f},
                               {-0.256515f, 0.352385f, 0.610348f},
                               {-0.704769f, -0.128258f, -0.222149f},
                               {0, -0.649519f, 0.375f},
                               {0.256515f, -0.352385f, -0.610348f}};
    for (int i = 0; i < 6; ++i) {
        const auto& s = std::get<NffSphere>(scene.objects[3 + i].primitive);
        EXPECT_EQ(s.center, centers[i]) << i;
        EXPECT_EQ(s.radius, 0.15f);
    }
    for (std::size_t i = 0; i < 9; ++i) {
        EXPECT_EQ(scene.objects[i].material, 0u);
        EXPECT_EQ(scene.objects[i].location.line, 11 + i);
        EXPECT_EQ(scene.objects[i].location.column, 1u);
    }
    EXPECT_EQ(scene.where(scene.objects[8].location).line, 19);
    EXPECT_EQ(scene.where(scene.objects[8].location).file, kJacks.string());
}

TEST(NffParser, GzippedJacksIsTheSame) {
    const NffScene plain = load_nff(kJacks);
    const NffScene gzipped = load_nff(kSource / "tests/data/spd/jacks.nff.gz");
    EXPECT_EQ(dump(gzipped), dump(plain));
    EXPECT_EQ(gzipped.objects.size(), 9u);
}

TEST(NffParser, ConeNumbersMayFollowOnTheSpecsTwoLines) {
    const std::string material = "f 1 1 1 1 0 0 0 0\n";
    const NffScene spd = parse_nff(material + "c 0 0 0 1 0 2 0 0.5\n", "a.nff");
    const NffScene spec = parse_nff(material + "c\n0 0 0 1\n0 2 0 0.5\n", "b.nff");
    EXPECT_EQ(dump(spd), dump(spec));
    const auto& c = std::get<NffCone>(spec.objects.at(0).primitive);
    EXPECT_EQ(c.apex, (Point3{0, 2, 0}));
    EXPECT_EQ(c.apex_radius, 0.5f);
}

TEST(NffParser, BackgroundMayComeBeforeOrAfterTheView) {
    const NffScene before = parse_nff(std::string("b 0.1 0.2 0.3\n") + kView, "a.nff");
    const NffScene after = parse_nff(std::string(kView) + "b 0.1 0.2 0.3\n", "a.nff");
    EXPECT_EQ(dump(before), dump(after));
    EXPECT_EQ(before.background, (Color{0.1f, 0.2f, 0.3f}));
    EXPECT_FALSE(parse_nff(kView, "a.nff").background);
}

TEST(NffParser, CommentsCrlfAndTheNumberFormsOfCsPercentG) {
    const std::string text =
        "# a comment line\r\n"
        "\r\n"
        "f 1 1 1 1 0 0 0 0 # a comment after an entity\r\n"
        "s -2.55836e-17 1e+01 -0 2.5E-3\r\n"
        "s +2 .5 5. 1\r\n"
        "\t s 0 0 1e-50 1#comment right after a number\n";
    const NffScene scene = parse_nff(text, "a.nff");
    ASSERT_EQ(scene.objects.size(), 3u);
    const auto& a = std::get<NffSphere>(scene.objects[0].primitive);
    EXPECT_EQ(a.center.x, -2.55836e-17f);
    EXPECT_EQ(a.center.y, 10);
    EXPECT_EQ(a.center.z, 0);
    EXPECT_TRUE(std::signbit(a.center.z));  // -0 is read as written
    EXPECT_EQ(a.radius, 2.5e-3f);
    const auto& b = std::get<NffSphere>(scene.objects[1].primitive);
    EXPECT_EQ(b.center, (Point3{2, 0.5f, 5}));
    EXPECT_EQ(scene.objects[1].location.line, 5u);
    EXPECT_EQ(scene.objects[2].location.column, 3u);  // after a tab and a space
    // Below the smallest float, a number underflows to zero, as strtof would have it.
    EXPECT_EQ(std::get<NffSphere>(scene.objects[2].primitive).center.z, 0);
    EXPECT_EQ(std::get<NffSphere>(scene.objects[2].primitive).radius, 1);
}

TEST(NffParser, LightColourIsOptional) {
    const NffScene scene = parse_nff("l 1 2 3\nl 4 5 6 0.5 0.25 1\nl 7 8 9\n", "a.nff");
    ASSERT_EQ(scene.lights.size(), 3u);
    EXPECT_FALSE(scene.lights[0].color);
    EXPECT_EQ(scene.lights[1].color, (Color{0.5f, 0.25f, 1}));
    EXPECT_EQ(scene.lights[2].position, (Point3{7, 8, 9}));
    EXPECT_EQ(scene.lights[2].location.line, 3u);
}

TEST(NffParser, EachObjectTakesTheLatestMaterial) {
    const NffScene scene = parse_nff(
        "f 1 0 0 1 0 0 0 0\ns 0 0 0 1\np 3\n0 0 0\n1 0 0\n0 1 0\n"
        "f 0 1 0 0.2 0.3 4 0.8 1.5\nc 0 0 0 1 0 1 0 0\n",
        "a.nff");
    ASSERT_EQ(scene.objects.size(), 3u);
    EXPECT_EQ(scene.objects[0].material, 0u);
    EXPECT_EQ(scene.objects[1].material, 0u);
    EXPECT_EQ(scene.objects[2].material, 1u);
    EXPECT_EQ(scene.materials[1].transmittance, 0.8f);
    EXPECT_EQ(scene.materials[1].ior, 1.5f);
    EXPECT_EQ(std::get<NffPolygon>(scene.objects[1].primitive).vertices.size(), 3u);
}

TEST(NffParser, PatchesKeepTheirNormalsAsWritten) {
    const NffScene scene =
        parse_nff("f 1 1 1 1 0 0 0 0\npp 3\n0 0 0 0 0 2\n1 0 0 0 0.1 1\n0 1 0 0 0 1\n", "a.nff");
    const auto& p = std::get<NffPatch>(scene.objects.at(0).primitive);
    ASSERT_EQ(p.normals.size(), 3u);
    EXPECT_EQ(p.normals[0], (Normal3{0, 0, 2}));
    EXPECT_EQ(p.normals[1], (Normal3{0, 0.1f, 1}));
    EXPECT_EQ(p.vertices[2], (Point3{0, 1, 0}));
}

TEST(NffParser, ConcaveGearFacesAndCollinearFirstCornersAreFine) {
    // NFF says the first three vertices make a convex corner; Newell's normal does not need it.
    const NffScene scene = parse_nff(
        "f 1 1 1 1 0 0 0 0\np 6\n3 1 0\n1 1 0\n1 3 0\n0 3 0\n0 0 0\n3 0 0\n"
        "p 5\n0 0 0\n1 0 0\n2 0 0\n2 2 0\n0 2 0\n",
        "a.nff");
    EXPECT_EQ(scene.objects.size(), 2u);
}

TEST(NffParser, AnEmptyFileHasNoViewAndRequireViewSaysSo) {
    const NffScene scene = parse_nff("# nothing here\n", "empty.nff");
    EXPECT_FALSE(scene.view);
    EXPECT_TRUE(scene.objects.empty());
    try {
        require_view(scene);
        ADD_FAILURE() << "no error";
    } catch (const SceneError& e) {
        EXPECT_EQ(e.location().file, "empty.nff");
        EXPECT_EQ(e.message(),
                  "the file has no view: NFF needs a \"v\" entity to place the camera");
    }
}

SceneError error_of(const std::string& text) {
    try {
        parse_nff(text, "bad.nff");
    } catch (const SceneError& e) {
        return e;
    }
    ADD_FAILURE() << "no error for: " << text;
    return SceneError({}, "");
}

TEST(NffParser, ErrorsQuoteTheLineAndUnderlineTheToken) {
    EXPECT_EQ(format_scene_error(error_of("f 1 1 1 1 0 0 0 0\ns 0 0 zero 1\n")),
              "bad.nff:2:7: error: expected a number for the sphere's center z, got \"zero\"\n"
              "    2 | s 0 0 zero 1\n"
              "      |       ^~~~\n");
    // At the end of the file, the caret stands just past the last token.
    EXPECT_EQ(format_scene_error(error_of("f 1 1 1 1 0 0 0 0\np 3\n0.5 0 0\n1 0 0\n0 1")),
              "bad.nff:5:4: error: the file ends inside the polygon that starts at line 2: "
              "expected the polygon's vertex 3 z\n"
              "    5 | 0 1\n"
              "      |    ^\n");
}

TEST(NffParser, LongTokensAndLinesAreNotQuotedWhole) {
    const std::string junk(100000, 'x');
    const SceneError e = error_of(junk);
    EXPECT_EQ(e.message(), "unknown NFF entity \"" + std::string(40, 'x') + "...\"");
    EXPECT_LE(e.source_line().size(), 4096u);
    std::string line = "f 1 1 1 1 0 0 0 0 ";
    for (int i = 0; i < 2000; ++i) line += "s 0 0 0 1 ";
    const SceneError far = error_of(line + "s 0 0 0 x\n");
    EXPECT_EQ(far.location().column, int(line.size()) + 9);
    EXPECT_TRUE(far.source_line().empty());  // beyond the quoted width
    EXPECT_EQ(format_scene_error(far).find('\n'), format_scene_error(far).size() - 1);
}

TEST(NffParser, HugeCountsAreRefusedBeforeMemoryIsTaken) {
    EXPECT_EQ(error_of("f 1 1 1 1 0 0 0 0\np 99999999999999999999999\n").message(),
              "a polygon of 99999999999999999999999 vertices is beyond the limit of 1000000");
    EXPECT_EQ(error_of("f 1 1 1 1 0 0 0 0\np 1000000\n0 0 0\n").message(),
              "the polygon claims 1000000 vertices, more than the rest of the file can hold");
}

TEST(NffParser, MangledInputGivesSceneErrorsOnly) {
    std::ifstream in(kJacks, std::ios::binary);
    const std::string jacks((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ASSERT_FALSE(jacks.empty());
    std::mt19937 rng(2024);
    const std::string alphabet = "0123456789 \n\t-+.eE#pcsflvbx";
    int errors = 0;
    for (int i = 0; i < 3000; ++i) {
        std::string text = jacks;
        const int edits = 1 + int(rng() % 4);
        for (int k = 0; k < edits; ++k) {
            const std::size_t at = rng() % text.size();
            switch (rng() % 3) {
                case 0:
                    text[at] = alphabet[rng() % alphabet.size()];
                    break;
                case 1:
                    text.erase(at, 1 + rng() % 8);
                    break;
                default:
                    text.insert(text.begin() + std::ptrdiff_t(at),
                                alphabet[rng() % alphabet.size()]);
            }
            if (text.empty()) text.push_back('x');
        }
        try {
            parse_nff(text, "mangled.nff");
        } catch (const SceneError& e) {
            ++errors;
            ASSERT_FALSE(e.message().empty());
            ASSERT_GE(e.location().line, 0);
        } catch (const std::exception& e) {
            FAIL() << "not a SceneError: " << e.what() << "\n" << text;
        }
    }
    EXPECT_GT(errors, 1000);
}

// dump() and where each entity starts.
std::string dump_with_locations(const NffScene& scene) {
    std::ostringstream out;
    const auto at = [&](NffLocation l) { out << l.line << ':' << l.column << ' '; };
    if (scene.view) at(scene.view->location);
    for (const NffLight& l : scene.lights) at(l.location);
    for (const NffMaterial& m : scene.materials) at(m.location);
    for (const NffObject& o : scene.objects) at(o.location);
    return dump(scene) + out.str();
}

// What parse_nff makes of text read in pieces of piece_bytes: the scene, or the error.
std::string parse_in_pieces_of(const std::string& text, std::size_t piece_bytes) {
    try {
        return dump_with_locations(parse_nff(text, "t.nff", piece_bytes));
    } catch (const SceneError& e) {
        return "error " + std::to_string(e.location().line) + ":" +
               std::to_string(e.location().column) + " " + e.message();
    }
}

TEST(NffParser, PiecesReadInParallelGiveWhatOneParserGives) {
    std::ifstream in(kJacks, std::ios::binary);
    const std::string jacks((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    // Materials changing between pieces, objects inheriting them, comments, and lines that
    // start with a keyword inside a view.
    std::string text = jacks + "# p 3 in a comment\nf 1 0 0 1 0 0 0 0\n";
    for (int i = 0; i < 200; ++i) {
        text += "s " + std::to_string(i) + " 0 0 1\n";
        if (i % 7 == 0) text += "f 0 " + std::to_string(i) + " 1 1 0 0 0 0\n";
        if (i % 5 == 0) text += "p 3\n0 0 0\n1 0 0\n0 1 " + std::to_string(i) + "\n";
        if (i % 11 == 0) text += "c 0 0 0 1\n  0 " + std::to_string(i + 1) + " 0 1\n";
    }
    const std::string whole = parse_in_pieces_of(text, kNffPieceBytes);
    EXPECT_EQ(whole.find("error"), std::string::npos) << whole;
    for (const std::size_t piece : {1, 16, 64, 200, 1000}) {
        EXPECT_EQ(parse_in_pieces_of(text, piece), whole) << piece;
    }
    // Errors in any piece are those of one parser; so are objects before any material.
    std::mt19937 rng(99);
    const std::string alphabet = "0123456789 \n\t-.epcsfvb";
    for (int i = 0; i < 300; ++i) {
        std::string mangled = text;
        for (int k = 0; k < 3; ++k) {
            mangled[rng() % mangled.size()] = alphabet[rng() % alphabet.size()];
        }
        if (i % 10 == 0) mangled.erase(0, jacks.size());
        ASSERT_EQ(parse_in_pieces_of(mangled, 1 + rng() % 300),
                  parse_in_pieces_of(mangled, kNffPieceBytes))
            << mangled;
    }
}

// Malformed files in tests/scene/bad_nff/, one error each, stated in the file's first line as
// `# error: LINE:COL: MESSAGE` (0:0 for an error without a location), with `# note: TEXT` lines
// after it for text that one of the error's notes must contain. Each file is loaded as a
// renderer would: load_nff_scene (load_nff, the pixel limit, then nff_to_scene).
const std::filesystem::path kBadDir = kSource / "tests/scene/bad_nff";

TEST(BadNffFiles, ThereAreAtLeast15) {
    EXPECT_GE(testing::files_with_extension(kBadDir, ".nff").size(), 15u);
}

TEST(BadNffFiles, EachGivesItsStatedError) {
    for (const auto& file : testing::files_with_extension(kBadDir, ".nff")) {
        testing::expect_stated_error(file, [&] { load_nff_scene(file); });
    }
}

}  // namespace
}  // namespace glint::nff_parser_test
