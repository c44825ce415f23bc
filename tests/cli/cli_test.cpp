// End-to-end tests of the glint tool: exit codes, messages, files written and not written.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "cli_fixture.h"
#include "common/under_sanitizer.h"
#include "glint/image/image_io.h"
#include "glint/image/srgb.h"
#include "glint/math/sanitizer_build.h"

namespace glint {
namespace {

TEST_F(Cli, VersionAndHelp) {
    const Outcome version = run_glint("--version");
    EXPECT_EQ(version.exit_code, 0);
    EXPECT_NE(version.out.find("glint "), std::string::npos);
    const Outcome help = run_glint("render --help");
    EXPECT_EQ(help.exit_code, 0);
    EXPECT_NE(help.out.find("--spp"), std::string::npos);
    EXPECT_NE(run_glint("--help").out.find("Examples"), std::string::npos);
}

TEST_F(Cli, UsageErrorsExitWithTwo) {
    EXPECT_EQ(run_glint("").exit_code, 2);
    EXPECT_EQ(run_glint("render").exit_code, 2);
    EXPECT_EQ(run_glint("paint x.yaml").exit_code, 2);
    EXPECT_EQ(run_glint("render " + scene("showcase.yaml") + " --width 0").exit_code, 2);
    EXPECT_EQ(run_glint("render " + scene("showcase.yaml") + " --max-depth 2000").exit_code, 2);
}

TEST_F(Cli, RenderHelpNamesEverySceneFormat) {
    const Outcome help = run_glint("render --help");
    for (const char* extension :
         {".yaml", ".nff", ".nff.gz", ".obj", ".ply", ".gltf", ".glb", ".stl"})
        EXPECT_NE(help.out.find(extension), std::string::npos) << extension << "\n" << help.out;
}

// CLI11's own check called "abc" out of range and let "--seed -1" wrap to 2^64 - 1.
TEST_F(Cli, NonNumericOptionValuesAreNamedAsSuch) {
    const std::map<std::string, std::string> expected = {
        {"--width abc", "--width: expected a whole number from 1 to 65536, got \"abc\""},
        {"--spp 1.5", "--spp: expected a whole number from 1 to 16777216, got \"1.5\""},
        {"--threads 2x", "--threads: expected a whole number from 0 to 4096, got \"2x\""},
        {"--max-depth 1025", "--max-depth: expected a whole number from 1 to 1024, got \"1025\""},
        {"--seed -1", "--seed: expected a whole number from 0 to 18446744073709551615, got \"-1\""},
    };
    for (const auto& [option, message] : expected) {
        const Outcome r = run_glint("render " + scene("showcase.yaml") + " -q " + option);
        EXPECT_EQ(r.exit_code, 2) << option;
        EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
    }
    EXPECT_EQ(
        run_glint("render " + scene("showcase.yaml") + " --width 8 -q --seed 18446744073709551615")
            .exit_code,
        0);
}

// Too little memory for the image (1 GB of address space, 3 GB of pixels) is reported in
// words, not as "std::bad_alloc". The sanitizers need far more address space than the limit.
TEST_F(Cli, OutOfMemoryIsReportedInWords) {
#ifdef GLINT_UNDER_SANITIZER
    GTEST_SKIP() << "the sanitizers' shadow memory does not fit under the limit";
#endif
    const Outcome r = run_glint("render " + scene("showcase.yaml") +
                                    " --width 20000 --height 13000 --threads 1 -q -o big.exr"
                                    " --max-memory 1T",  // past the estimate, into the limit
                                "ulimit -v 1000000 && ");
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_EQ(r.err,
              "glint: error: out of memory: the scene or image is too large for this machine\n");
    EXPECT_FALSE(fs::exists(dir_ / "big.exr"));
}

TEST_F(Cli, ARenderTooLargeForItsMemoryIsRefusedBeforeBuilding) {
    // 4000 x 3000 pixels of the gaussian film at 84 bytes a pixel, and 4 MiB of file buffers:
    // 965 MiB.
    const Outcome r = run_glint("render " + scene("showcase.yaml") +
                                " --width 4000 --filter gaussian -q -o big.png --max-memory 64M");
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("glint: error: the render needs about "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("the film 965 MiB for 4000x3000 pixels"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("more than the 64 MiB --max-memory allows"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "big.png"));

    EXPECT_EQ(
        run_glint("render " + scene("showcase.yaml") + " --width 40 -q --max-memory 64M").exit_code,
        0);
    const Outcome bad = run_glint("render " + scene("showcase.yaml") + " --max-memory lots");
    EXPECT_EQ(bad.exit_code, 2);
    EXPECT_NE(bad.err.find("expected a size such as 512M or 16G, got \"lots\""), std::string::npos)
        << bad.err;
}

TEST_F(Cli, MaxFileSizeLimitsEveryFileTheSceneReads) {
    const Outcome r =
        run_glint("render " + scene("features/meshes.yaml") + " --width 40 -q --max-file-size 64K");
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("spot.obj: error: file is 330652 bytes, more than the limit of 65536 "
                         "bytes"),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("note: raise the limit with --max-file-size SIZE"), std::string::npos)
        << r.err;
    EXPECT_EQ(
        run_glint("render " + scene("features/meshes.yaml") + " --width 40 -q --max-file-size 1M")
            .exit_code,
        0);
    const Outcome bench =
        run_glint("bench " + scene("features/meshes.yaml") + " --rays 100 --max-file-size 64K");
    EXPECT_EQ(bench.exit_code, 2) << bench.err;
    EXPECT_EQ(run_glint("render " + scene("showcase.yaml") + " --max-file-size 1.5").exit_code, 2);
}

TEST_F(Cli, RendersAndSummarisesTheRays) {
    const Outcome r = run_glint("render " + scene("showcase.yaml") + " --width 40 --spp 1");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Image image = read_image(dir_ / "showcase.png");  // default: the scene's name
    EXPECT_EQ(image.width, 40);
    EXPECT_EQ(image.height, 30);  // the scene's 4:3 aspect kept
    EXPECT_NE(r.out.find("Mrays/s"), std::string::npos);
    EXPECT_NE(r.out.find("primary"), std::string::npos);
    EXPECT_NE(r.out.find("refracted"), std::string::npos);
}

TEST_F(Cli, QuietPrintsNothing) {
    const Outcome r =
        run_glint("render " + scene("showcase.yaml") + " --width 16 --spp 1 -q -o a.png");
    EXPECT_EQ(r.exit_code, 0);
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(r.err, "");
}

TEST_F(Cli, StatsFileHasTheDocumentedKeys) {
    const Outcome r = run_glint("render " + scene("showcase.yaml") +
                                " --width 20 --height 10 --spp 4 -q -o a.png --stats s.json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::string json = slurp(dir_ / "s.json");
    for (const char* key :
         {"\"scene\"", "\"output\"", "\"width\": 20", "\"height\": 10", "\"samples_per_pixel\": 4",
          "\"threads\"", "\"seconds\"", "\"primary\": 800", "\"primary_hits\"", "\"shadow\"",
          "\"reflected\"", "\"refracted\"", "\"total\"", "\"mrays_per_second\"",
          "\"bad_samples\": 0", "\"complete\": true"})
        EXPECT_NE(json.find(key), std::string::npos) << key << " missing from\n" << json;
    // Where the process's time went: each part measured, and all within the process's time.
    const auto seconds = [&](const std::string& key) {
        const std::size_t times = json.find("\"times\": {");
        const std::size_t at = json.find("\"" + key + "\": ", times);
        EXPECT_NE(at, std::string::npos) << key << " missing from\n" << json;
        return std::stod(json.substr(at + key.size() + 4));
    };
    double parts = 0;
    for (const char* part : {"load", "build", "render", "write"}) {
        EXPECT_GE(seconds(part), 0.0) << part;
        parts += seconds(part);
    }
    EXPECT_GT(seconds("render"), 0.0);
    EXPECT_LE(parts, seconds("process"));
}

TEST_F(Cli, EveryImageFormatIsWritten) {
    for (const char* name : {"a.png", "a.ppm", "a.pfm", "a.exr"}) {
        const Outcome r =
            run_glint("render " + scene("showcase.yaml") + " --width 24 --spp 1 -q -o " + name);
        ASSERT_EQ(r.exit_code, 0) << name << ": " << r.err;
        EXPECT_EQ(read_image(dir_ / name).width, 24) << name;
    }
    ASSERT_EQ(run_glint("render " + scene("showcase.yaml") + " --width 4 -q -o b.ppm --ppm-ascii")
                  .exit_code,
              0);
    EXPECT_EQ(slurp(dir_ / "b.ppm").substr(0, 2), "P3");
    EXPECT_EQ(slurp(dir_ / "a.ppm").substr(0, 2), "P6");
}

TEST_F(Cli, ThreadCountDoesNotChangeTheImage) {
    ASSERT_EQ(
        run_glint("render " + scene("showcase.yaml") + " --width 64 -q -o one.pfm --threads 1")
            .exit_code,
        0);
    ASSERT_EQ(
        run_glint("render " + scene("showcase.yaml") + " --width 64 -q -o two.pfm --threads 3")
            .exit_code,
        0);
    EXPECT_TRUE(slurp(dir_ / "one.pfm") == slurp(dir_ / "two.pfm"));
}

TEST_F(Cli, BadSceneExitsWithTwoAndACompilerStyleError) {
    write_scene("bad.yaml",
                "camera: {from: [0, 0, -5], at: [0, 0, 0]}\n"
                "objects:\n"
                "  - {type: spere, center: [0, 0, 0], radius: 1}\n");
    std::ofstream(dir_ / "bad.png") << "an older image";
    const Outcome r = run_glint("render bad.yaml");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("bad.yaml:3:12: error: unknown object type \"spere\""), std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("did you mean \"sphere\"?"), std::string::npos) << r.err;
    EXPECT_EQ(slurp(dir_ / "bad.png"), "an older image");  // untouched
}

TEST_F(Cli, MissingSceneAndUnknownFormatsExitWithTwo) {
    const Outcome missing = run_glint("render nowhere.yaml");
    EXPECT_EQ(missing.exit_code, 2);
    EXPECT_NE(missing.err.find("nowhere.yaml"), std::string::npos);
    const Outcome scene_format = run_glint("render scene.obj3");
    EXPECT_EQ(scene_format.exit_code, 2);
    EXPECT_NE(scene_format.err.find("unknown scene format"), std::string::npos);
    const Outcome image_format = run_glint("render " + scene("showcase.yaml") + " -o out.gif");
    EXPECT_EQ(image_format.exit_code, 2);
    EXPECT_NE(image_format.err.find("unknown image format \".gif\""), std::string::npos);
    EXPECT_FALSE(fs::exists(dir_ / "out.gif"));
}

TEST_F(Cli, RendersNffAndModelFilesDirectly) {
    const std::string data = std::string("'") + GLINT_SOURCE_DIR + "/tests/data/";
    for (const char* file :
         {"spd/jacks.nff'", "spd/jacks.nff.gz'", "meshes/quad.gltf'", "meshes/cube_binary.ply'",
          "meshes/tetra_ascii.stl'", "meshes/spot.obj'"}) {
        const Outcome r = run_glint("render " + data + file + " --width 32 -q -o a.png");
        EXPECT_EQ(r.exit_code, 0) << file << ": " << r.err;
        EXPECT_EQ(read_image(dir_ / "a.png").width, 32) << file;
    }
}

// One JSON object a line per structure, ray set and thread count, with the documented keys,
// and the same hit counts for every exact structure.
TEST_F(Cli, BenchPrintsOneJsonLinePerStructureRaySetAndThreadCount) {
    const std::string jacks = std::string("'") + GLINT_SOURCE_DIR + "/tests/data/spd/jacks.nff'";
    const Outcome r =
        run_glint("bench " + jacks + " --json --rays 2000 --threads 2 --accel bvh,grid,kdtree");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    std::istringstream lines(r.out);
    std::string line;
    int count = 0;
    std::map<std::string, std::string> hits_by_set;
    while (std::getline(lines, line)) {
        ++count;
        for (const char* key : {"\"accel\": ", "\"scene\": ", "\"rays\": ", "\"threads\": ",
                                "\"build_s\": ", "\"mrays_per_s\": ", "\"bytes_per_prim\": "})
            EXPECT_NE(line.find(key), std::string::npos) << key << " in " << line;
        const auto field = [&](const std::string& key) {
            const std::size_t at = line.find("\"" + key + "\": ") + key.size() + 4;
            return line.substr(at, line.find_first_of(",}", at) - at);
        };
        const std::string set = field("rays"), hits = field("hits");
        EXPECT_TRUE(set == "\"primary\"" || set == "\"incoherent\"" || set == "\"shadow\"") << set;
        const auto [it, added] = hits_by_set.try_emplace(set, hits);
        EXPECT_EQ(it->second, hits) << line;  // every structure finds the same hits
    }
    EXPECT_EQ(count, 3 * 3 * 2);  // structures x ray sets x {1, 2} threads
    EXPECT_EQ(r.err, "");
}

// --ray-set traces only the sets named, and each as in a full run.
TEST_F(Cli, BenchRaySetTracesOnlyTheSetsNamed) {
    const std::string jacks = std::string("'") + GLINT_SOURCE_DIR + "/tests/data/spd/jacks.nff'";
    const std::string common = "bench " + jacks + " --json --rays 1000 --threads 1 --accel bvh";
    const Outcome all = run_glint(common);
    const Outcome shadow = run_glint(common + " --ray-set shadow");
    const Outcome two = run_glint(common + " --ray-set primary,shadow");
    ASSERT_EQ(all.exit_code, 0) << all.err;
    ASSERT_EQ(shadow.exit_code, 0) << shadow.err;
    ASSERT_EQ(two.exit_code, 0) << two.err;
    const auto hits_by_set = [](const std::string& out) {
        std::map<std::string, std::string> hits;
        std::istringstream lines(out);
        std::string line;
        while (std::getline(lines, line)) {
            const auto field = [&](const std::string& key) {
                const std::size_t at = line.find("\"" + key + "\": ") + key.size() + 4;
                return line.substr(at, line.find_first_of(",}", at) - at);
            };
            hits[field("rays")] = field("hits");
        }
        return hits;
    };
    const auto every = hits_by_set(all.out);
    ASSERT_EQ(every.size(), 3u);
    EXPECT_EQ(hits_by_set(shadow.out),
              (std::map<std::string, std::string>{{"\"shadow\"", every.at("\"shadow\"")}}));
    EXPECT_EQ(hits_by_set(two.out),
              (std::map<std::string, std::string>{{"\"primary\"", every.at("\"primary\"")},
                                                  {"\"shadow\"", every.at("\"shadow\"")}}));
}

// --packets adds a row for each set traced in packets of eight, which finds the same hits.
TEST_F(Cli, BenchPacketsTraceEachSetInPacketsToo) {
    const std::string jacks = std::string("'") + GLINT_SOURCE_DIR + "/tests/data/spd/jacks.nff'";
    const Outcome r = run_glint("bench " + jacks +
                                " --json --rays 1000 --threads 1 --accel bvh,kdtree --packets");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    std::istringstream lines(r.out);
    std::string line;
    std::map<std::string, int> rows_by_packet;
    std::map<std::string, std::string> hits_by_set;
    while (std::getline(lines, line)) {
        const auto field = [&](const std::string& key) {
            const std::size_t at = line.find("\"" + key + "\": ") + key.size() + 4;
            return line.substr(at, line.find_first_of(",}", at) - at);
        };
        ++rows_by_packet[field("packet")];
        const auto [it, added] = hits_by_set.try_emplace(field("rays"), field("hits"));
        EXPECT_EQ(it->second, field("hits")) << line;
    }
    EXPECT_EQ(rows_by_packet, (std::map<std::string, int>{{"1", 6}, {"8", 6}}));
    const Outcome table =
        run_glint("bench " + jacks + " --rays 500 --threads 1 --accel bvh --packets");
    EXPECT_NE(table.out.find("bvh      primary x8"), std::string::npos) << table.out;
    EXPECT_NE(table.out.find("hit counts agree"), std::string::npos) << table.out;
}

TEST_F(Cli, BenchTableAndBadInput) {
    const std::string jacks = std::string("'") + GLINT_SOURCE_DIR + "/tests/data/spd/jacks.nff'";
    const Outcome table = run_glint("bench " + jacks + " --rays 500 --threads 1 --accel list");
    EXPECT_EQ(table.exit_code, 0) << table.err;
    EXPECT_NE(table.out.find("list     primary"), std::string::npos) << table.out;
    EXPECT_NE(table.out.find("hit counts agree"), std::string::npos) << table.out;

    EXPECT_EQ(run_glint("bench " + jacks + " --accel octree").exit_code, 2);
    EXPECT_EQ(run_glint("bench " + jacks + " --ray-set diffuse").exit_code, 2);
    EXPECT_EQ(run_glint("bench " + jacks + " --rays 0").exit_code, 2);
    write_scene("bad.nff", "v\nfrom 0 0 -5\nat 0 0 0\nup 0 1 0\nangle x\n");
    const Outcome bad = run_glint("bench bad.nff");
    EXPECT_EQ(bad.exit_code, 2);
    EXPECT_NE(bad.err.find("bad.nff:5:7: error:"), std::string::npos) << bad.err;
}

// The showcase's counts, structure and warnings as text: 6 objects (a plane among them, beside
// the structure) and 2 point lights; its five materials' kd + ks + reflect + transmit exceed 1.
TEST_F(Cli, InfoDescribesTheShowcase) {
    const Outcome r = run_glint("info " + scene("showcase.yaml"));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    for (const char* line :
         {"Image        800x600, 9 spp, whitted integrator, max depth 8\n",
          "Objects      6: box 1, plane 1, sphere 4\n", "Triangles    0\n", "Materials    5\n",
          "Lights       2: 2 point; 0 emitting objects\n",
          "Bounds       (-4.2, 0, -3.05) to (2.9, 2.6, 4.9); 1 unbounded object (a plane) beside\n",
          "Acceleration structure: bvh\n", "  references   5 in leaves\n", "No warnings\n",
          "5 notes\n",
          "/scenes/showcase.yaml:20:3: material \"glass\": kd + ks + reflect + transmit",
          "1.88 > 1"})
        EXPECT_NE(r.out.find(line), std::string::npos) << line << " missing from\n" << r.out;
    const Outcome grid = run_glint("info " + scene("showcase.yaml") + " --accel grid");
    EXPECT_EQ(grid.exit_code, 0) << grid.err;
    EXPECT_NE(grid.out.find("Acceleration structure: grid\n  cells        "), std::string::npos)
        << grid.out;
}

// A sky image is described, and whether the integrator takes its light.
TEST_F(Cli, InfoDescribesTheSky) {
    const Outcome r = run_glint("info " + scene("features/sky.yaml"));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("Sky          an image of 256x128 pixels: it lights the scene\n"),
              std::string::npos)
        << r.out;
    EXPECT_EQ(r.out.find("[no-lights]"), std::string::npos) << r.out;
    const Outcome json = run_glint("info " + scene("features/sky.yaml") + " --json");
    EXPECT_NE(json.out.find("\"sky\": {\"width\": 256, \"height\": 128},"), std::string::npos)
        << json.out;
}

// An animation's frames and moving lights are described.
TEST_F(Cli, InfoDescribesAnAnimation) {
    const Outcome r = run_glint("info " + scene("features/animation.yaml"));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("Animation    24 frames at 8 fps (3 s; frame 0 is described here); 2 "
                         "lights move\n"),
              std::string::npos)
        << r.out;
    const Outcome json = run_glint("info " + scene("features/animation.yaml") + " --json");
    EXPECT_NE(json.out.find("\"animation\": {\"frames\": 24, \"fps\": 8, \"moving_lights\": 2},"),
              std::string::npos)
        << json.out;
}

// The same as one JSON object with the documented keys, one a line where they are numbers.
TEST_F(Cli, InfoJsonHasTheDocumentedKeys) {
    const Outcome r = run_glint("info " + scene("showcase.yaml") + " --json --accel kdtree");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    ASSERT_FALSE(r.out.empty());
    EXPECT_EQ(r.out.front(), '{');
    EXPECT_EQ(r.out.substr(r.out.size() - 2), "}\n");
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '{'),
              std::count(r.out.begin(), r.out.end(), '}'));
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '['),
              std::count(r.out.begin(), r.out.end(), ']'));
    for (const char* key :
         {"\"image\": {\"width\": 800, \"height\": 600, \"samples_per_pixel\": 9, "
          "\"integrator\": \"whitted\", \"max_depth\": 8}",
          "\"objects\": {\"total\": 6, \"by_shape\": {\"box\": 1, \"plane\": 1, \"sphere\": 4}}",
          "\"triangles\": 0,",
          "\"materials\": 5,",
          "\"lights\": {\"point\": 2, \"spot\": 0, \"directional\": 0, \"area\": 0, "
          "\"emitting_objects\": 0}",
          "\"animation\": null,",
          "\"sky\": null,",
          "\"bounds\": {\"min\": [-4.2, 0, -3.05], \"max\": [2.9, 2.6, 4.9], "
          "\"unbounded_objects\": 1}",
          "\"name\": \"kdtree\",",
          "\"available\": true,",
          "\"interior_nodes\": ",
          "\"leaves\": ",
          "\"empty_leaves\": ",
          "\"max_depth\": ",
          "\"mean_leaf_depth\": ",
          "\"min_leaf_size\": ",
          "\"mean_leaf_size\": ",
          "\"max_leaf_size\": ",
          "\"references\": ",
          "\"unbounded\": 1,",
          "\"sah_cost\": ",
          "\"sah_traversal_cost\": 1,",
          "\"sah_intersection_cost\": 1,",
          "\"memory_bytes\": ",
          "{\"rule\": \"energy\", \"severity\": \"note\", \"subject\": \"material "
          "\\\"floor\\\"\", \"message\": ",
          "/scenes/showcase.yaml\", \"line\": 13, \"column\": 3}"})
        EXPECT_NE(r.out.find(key), std::string::npos) << key << " missing from\n" << r.out;
}

TEST_F(Cli, InfoWarnsAboutASceneWithoutLightsAndExitsWithZero) {
    write_scene("dark.yaml",
                "camera: {from: [0, 0, -5], at: [0, 0, 0]}\n"
                "materials: {spare: {kd: 0.5}}\n"
                "objects:\n"
                "  - {type: sphere, center: [0, 0, 0], radius: 1}\n"
                "  - {type: sphere, center: [0, 0, -5], radius: 0.5}\n");
    const Outcome r = run_glint("info dark.yaml");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    for (const char* warning :
         {"  scene: the scene has no lights and no emitting objects", "[no-lights]",
          "  dark.yaml:5:5: camera: the camera at (0, 0, -5) is inside object 1 (sphere)",
          "[camera-inside]",
          "  dark.yaml:2:13: material \"spare\": is defined but no object uses it "
          "[unused-material]"})
        EXPECT_NE(r.out.find(warning), std::string::npos) << warning << " missing from\n" << r.out;
    EXPECT_NE(r.out.find("3 warnings\n"), std::string::npos) << r.out;
}

TEST_F(Cli, InfoOfABadSceneExitsWithTwoAsRenderDoes) {
    write_scene("bad.yaml",
                "camera: {from: [0, 0, -5], at: [0, 0, 0]}\n"
                "objects:\n"
                "  - {type: spere, center: [0, 0, 0], radius: 1}\n");
    const Outcome r = run_glint("info bad.yaml --json");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_TRUE(r.out.empty()) << r.out;
    EXPECT_NE(r.err.find("bad.yaml:3:12: error: unknown object type \"spere\""), std::string::npos)
        << r.err;
    EXPECT_EQ(run_glint("info nowhere.yaml").exit_code, 2);
    EXPECT_EQ(run_glint("info " + scene("showcase.yaml") + " --accel octree").exit_code, 2);
}

TEST_F(Cli, InfoReadsNffAndModelFiles) {
    const std::string data = std::string("'") + GLINT_SOURCE_DIR + "/tests/data/";
    const Outcome nff = run_glint("info " + data + "spd/jacks.nff'");
    EXPECT_EQ(nff.exit_code, 0) << nff.err;
    const Outcome mesh = run_glint("info " + data + "meshes/cube_binary.ply'");
    EXPECT_EQ(mesh.exit_code, 0) << mesh.err;
    EXPECT_NE(mesh.out.find("Triangles    12\n"), std::string::npos) << mesh.out;
}

// A scene asking for more than a default limit is refused with the way to raise it; raised, it
// renders (its samples replaced by --spp, which the limits do not bound).
TEST_F(Cli, LimitsOnWhatASceneAsksAreRaisedByFlags) {
    write_scene("deep.yaml",
                "camera: {from: [0, 0, -5], at: [0, 0, 0]}\n"
                "image: {width: 8, height: 6, samples: 70000, sampler: jittered, max_depth: 100}\n"
                "objects: [{type: sphere, center: [0, 0, 0], radius: 1}]\n");
    const std::string render = "render deep.yaml --spp 2 -q -o a.png";
    const Outcome samples = run_glint(render);
    EXPECT_EQ(samples.exit_code, 2);
    EXPECT_NE(samples.err.find("deep.yaml:2:39: error: samples 70000 is more than the limit of "
                               "65536"),
              std::string::npos)
        << samples.err;
    EXPECT_NE(samples.err.find("note: raise the limit with --max-samples N"), std::string::npos);
    const Outcome depth = run_glint(render + " --max-samples 70000");
    EXPECT_EQ(depth.exit_code, 2);
    EXPECT_NE(depth.err.find("max_depth 100 is more than the limit of 64"), std::string::npos)
        << depth.err;
    EXPECT_FALSE(fs::exists(dir_ / "a.png"));
    const Outcome raised = run_glint(render + " --max-samples 70000 --max-ray-depth 100");
    EXPECT_EQ(raised.exit_code, 0) << raised.err;
    EXPECT_TRUE(fs::exists(dir_ / "a.png"));
    const Outcome info = run_glint("info deep.yaml --max-samples 70000 --max-ray-depth 100");
    EXPECT_EQ(info.exit_code, 0) << info.err;
    for (const char* bad : {"--max-pixels 0", "--max-samples 20000000", "--max-ray-depth 2000"}) {
        const Outcome usage = run_glint(render + " " + bad);
        EXPECT_EQ(usage.exit_code, 2) << bad;
        EXPECT_NE(usage.err.find("expected a whole number"), std::string::npos) << usage.err;
    }
}

// A scene reads only under its own folder unless --allow-read (repeatable, on render and bench)
// names another; a folder that does not exist is bad usage.
TEST_F(Cli, AllowReadLetsASceneReadAnotherFolder) {
    fs::create_directories(dir_ / "scene");
    fs::create_directories(dir_ / "models");
    fs::create_directories(dir_ / "more");
    const fs::path meshes = fs::path(GLINT_SOURCE_DIR) / "tests/data/meshes";
    fs::copy_file(meshes / "tetra_ascii.stl", dir_ / "models" / "tetra.stl");
    fs::copy_file(meshes / "cube_ascii.ply", dir_ / "more" / "cube.ply");
    write_scene("scene/s.yaml",
                "camera: {from: [0, 1, -5], at: [0, 0, 0]}\n"
                "lights: [{type: point, position: [0, 5, -5]}]\n"
                "objects:\n"
                "  - {type: mesh, file: ../models/tetra.stl}\n"
                "  - {type: mesh, file: ../more/cube.ply}\n");
    const std::string render = "render scene/s.yaml --width 8 --spp 1 -q -o a.png";

    const Outcome refused = run_glint(render);
    EXPECT_EQ(refused.exit_code, 2);
    EXPECT_NE(refused.err.find("scene/s.yaml:4:24: error: mesh file \"../models/tetra.stl\" is "
                               "outside the folders the scene may read"),
              std::string::npos)
        << refused.err;
    EXPECT_NE(refused.err.find("note: allow the folder with --allow-read DIR"), std::string::npos);
    EXPECT_FALSE(fs::exists(dir_ / "a.png"));

    const Outcome one = run_glint(render + " --allow-read models");
    EXPECT_EQ(one.exit_code, 2);
    EXPECT_NE(one.err.find("mesh file \"../more/cube.ply\""), std::string::npos) << one.err;

    const Outcome both = run_glint(render + " --allow-read models --allow-read more");
    EXPECT_EQ(both.exit_code, 0) << both.err;
    EXPECT_TRUE(fs::exists(dir_ / "a.png"));
    // Before the scene, too: each --allow-read takes one folder.
    EXPECT_EQ(run_glint("render --allow-read models --allow-read more scene/s.yaml --width 8 "
                        "--spp 1 -q -o b.png")
                  .exit_code,
              0);

    const Outcome bench = run_glint(
        "bench scene/s.yaml --rays 200 --threads 1 --accel bvh --allow-read models "
        "--allow-read more");
    EXPECT_EQ(bench.exit_code, 0) << bench.err;
    EXPECT_EQ(run_glint("bench scene/s.yaml --rays 200 --threads 1 --accel bvh").exit_code, 2);

    for (const std::string verb : {"render scene/s.yaml -q", "bench scene/s.yaml"}) {
        const Outcome missing = run_glint(verb + " --allow-read nowhere");
        EXPECT_EQ(missing.exit_code, 2) << verb;
        EXPECT_NE(missing.err.find("nowhere"), std::string::npos) << missing.err;
        const Outcome file = run_glint(verb + " --allow-read scene/s.yaml");
        EXPECT_EQ(file.exit_code, 2) << verb;
    }
}

TEST_F(Cli, BadNffExitsWithTwoAtTheOffendingToken) {
    write_scene("bad.nff",
                "v\nfrom 0 0 -5\nat 0 0 0\nup 0 1 0\nangle 45\nhither 1\n"
                "resolution 8 8\nf 1 0 0 1 0 0 0 0\ns 0 0 0 radius\n");
    const Outcome r = run_glint("render bad.nff");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("bad.nff:9:9: error:"), std::string::npos) << r.err;
}

TEST_F(Cli, NonSquareSampleCountIsRejectedForTheRegularSamplerOnly) {
    const Outcome r = run_glint("render " + scene("showcase.yaml") + " --spp 5");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("with --spp 5: samples must be a square number"), std::string::npos)
        << r.err;
    const Outcome jittered =
        run_glint("render " + scene("showcase.yaml") +
                  " --spp 5 --sampler jittered --width 16 -q -o " + (dir_ / "five.png").string());
    EXPECT_EQ(jittered.exit_code, 0) << jittered.err;
}

// What a scene file may not ask for, the command line may not either: the same check of the
// settings as a whole, on the scene's settings with the options applied.
TEST_F(Cli, OptionsCannotGetRoundTheSceneFilesChecksOfAdaptiveSampling) {
    const std::string adaptive = scene("features/adaptive.yaml");  // min_samples 16, samples 256
    const Outcome regular = run_glint("render " + adaptive + " --sampler regular --spp 16");
    EXPECT_EQ(regular.exit_code, 2);
    EXPECT_NE(regular.err.find("with --spp 16 --sampler regular: adaptive sampling needs the "
                               "jittered or sobol sampler"),
              std::string::npos)
        << regular.err;
    const Outcome few = run_glint("render " + adaptive + " --spp 8");
    EXPECT_EQ(few.exit_code, 2);
    EXPECT_NE(few.err.find("with --spp 8: adaptive min_samples (16) exceeds the image's samples "
                           "(8)"),
              std::string::npos)
        << few.err;
    // explain takes the same options through the same check.
    const Outcome explained =
        run_glint("explain " + adaptive + " --pixel 0,0 --sampler regular --spp 16");
    EXPECT_EQ(explained.exit_code, 2);
    EXPECT_NE(explained.err.find("needs the jittered or sobol sampler"), std::string::npos)
        << explained.err;
    // At min_samples the render goes ahead.
    const Outcome ok = run_glint("render " + adaptive + " --spp 16 --width 24 -q -o ok.png");
    EXPECT_EQ(ok.exit_code, 0) << ok.err;
}

// --shadows map goes through the same check as the scene's shadows: map.
TEST_F(Cli, ShadowMapsFromTheCommandLineAreCheckedAsTheScenesAre) {
    const Outcome path =
        run_glint("render " + scene("features/cornell-box.yaml") + " --shadows map -q -o p.png");
    EXPECT_EQ(path.exit_code, 2);
    EXPECT_NE(path.err.find("with --shadows map: shadow maps are for the whitted and distributed "
                            "integrators, not path"),
              std::string::npos)
        << path.err;
    const Outcome glass = run_glint("render " + scene("features/transparent-shadows.yaml") +
                                    " --shadows map -q -o g.png");
    EXPECT_EQ(glass.exit_code, 2);
    EXPECT_NE(glass.err.find("transparent shadows need shadow feelers"), std::string::npos)
        << glass.err;
    const Outcome ok = run_glint("render " + scene("features/shadows.yaml") +
                                 " --shadows map --width 32 -o ok.png");
    EXPECT_EQ(ok.exit_code, 0) << ok.err;
    EXPECT_NE(ok.out.find("shadow-map lookups"), std::string::npos) << ok.out;
}

// Cones are not rays: explain and the output variables refuse the cone integrator; a render and
// glint info take it, info telling which objects it sees by their axis ray alone.
TEST_F(Cli, TheConeIntegratorRendersAndExplainAndAovsRefuseIt) {
    const Outcome explain =
        run_glint("explain " + scene("features/cone-tracing.yaml") + " --pixel 10,10");
    EXPECT_EQ(explain.exit_code, 2);
    EXPECT_NE(explain.err.find("explain follows rays, and the cone integrator traces cones"),
              std::string::npos)
        << explain.err;
    const Outcome aov =
        run_glint("render " + scene("features/cone-tracing.yaml") + " --aov depth -q -o cone.exr");
    EXPECT_EQ(aov.exit_code, 2);
    EXPECT_NE(aov.err.find("--aov: the output variables follow rays"), std::string::npos)
        << aov.err;
    const Outcome ok = run_glint("render " + scene("features/cone-tracing.yaml") +
                                 " --width 48 --height 27 -q -o cone.png");
    EXPECT_EQ(ok.exit_code, 0) << ok.err;
    const Outcome info = run_glint("info " + scene("features/cone-tracing.yaml"));
    EXPECT_EQ(info.exit_code, 0) << info.err;
    EXPECT_NE(info.out.find("object 8 (box): has no cone test"), std::string::npos) << info.out;
}

// Beams are not rays either; and a scene with a curved shape, a lens or Fresnel's weights is
// refused for the beam integrator at its place in the file.
TEST_F(Cli, TheBeamIntegratorRendersPolygonsAndRefusesWhatItCannotTrace) {
    const Outcome ok = run_glint("render " + scene("features/beam-tracing.yaml") +
                                 " --width 48 --height 30 -o beam.png");
    EXPECT_EQ(ok.exit_code, 0) << ok.err;
    EXPECT_NE(ok.out.find("reflected"), std::string::npos) << ok.out;  // beams, counted
    const Outcome explain =
        run_glint("explain " + scene("features/beam-tracing.yaml") + " --pixel 10,10");
    EXPECT_EQ(explain.exit_code, 2);
    EXPECT_NE(explain.err.find("explain follows rays, and the beam integrator traces beams"),
              std::string::npos)
        << explain.err;
    const Outcome aov =
        run_glint("render " + scene("features/beam-tracing.yaml") + " --aov depth -q -o b.exr");
    EXPECT_EQ(aov.exit_code, 2);
    EXPECT_NE(aov.err.find("the beam integrator traces beams"), std::string::npos) << aov.err;

    const std::string head =
        "image: {width: 8, height: 8, integrator: beam}\n"
        "camera: {from: [0, 0, -5], at: [0, 0, 0]}\n";
    const fs::path curved = write_scene(
        "curved.yaml", head +
                           "materials:\n  m: {color: [1, 1, 1]}\nobjects:\n"
                           "  - {type: polygon, vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "
                           "material: m}\n"
                           "  - {type: sphere, center: [0, 0, 1], radius: 1, material: m}\n");
    const Outcome sphere = run_glint("render '" + curved.string() + "' -o c.png");
    EXPECT_EQ(sphere.exit_code, 2);
    EXPECT_NE(sphere.err.find("curved.yaml:7:5: error: object 1 is a sphere, which is curved"),
              std::string::npos)
        << sphere.err;
    EXPECT_FALSE(fs::exists(dir_ / "c.png"));
    const fs::path fresnel = write_scene(
        "fresnel.yaml", head +
                            "materials:\n  glass: {transmit: 0.9, ior: 1.5, fresnel: true}\n"
                            "objects:\n"
                            "  - {type: box, min: [0, 0, 0], max: [1, 1, 1], "
                            "material: glass}\n");
    const Outcome glass = run_glint("render '" + fresnel.string() + "' -o f.png");
    EXPECT_EQ(glass.exit_code, 2);
    EXPECT_NE(glass.err.find("fresnel.yaml:4:3: error: material 'glass' has fresnel: true"),
              std::string::npos)
        << glass.err;
}

// The samples image: the counts themselves in a float format; in a PNG a linear ramp of grey,
// the 8-bit value 255 count / most (not sRGB-encoded, which would show half the samples as 73%).
TEST_F(Cli, TheSamplesImageIsALinearRampOfTheCounts) {
    const Outcome r = run_glint("render " + scene("features/adaptive.yaml") +
                                " --width 48 -q -o a.png --samples-image n.exr");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Outcome png = run_glint("render " + scene("features/adaptive.yaml") +
                                  " --width 48 -q -o a.png --samples-image n.png");
    ASSERT_EQ(png.exit_code, 0) << png.err;
    const Image counts = read_image(dir_ / "n.exr"), grey = read_image(dir_ / "n.png");
    ASSERT_EQ(counts.pixels.size(), grey.pixels.size());
    float fewest = 256, most = 0;
    for (std::size_t i = 0; i < counts.pixels.size(); ++i) {
        const float n = counts.pixels[i].r;
        fewest = std::min(fewest, n);
        most = std::max(most, n);
        // Read back as linear light: encoded again it is the 8-bit value, within its rounding
        // and dither.
        EXPECT_NEAR(linear_to_srgb(grey.pixels[i].r), n / 256, 1.0 / 255) << i << ": " << n;
    }
    EXPECT_EQ(fewest, 16);  // the scene's min_samples: the flat sky
    EXPECT_GT(most, 64);
}

// The output is checked before the scene is even read (here it does not exist), so a path that
// cannot take the image fails at once, not after a long render.
TEST_F(Cli, UnwritableOutputIsRejectedBeforeLoading) {
    fs::create_directories(dir_ / "taken.png");
    std::ofstream(dir_ / "file.txt") << "not a directory";
    const std::map<std::string, std::string> expected = {
        {"taken.png", "cannot write \"taken.png\": it is a directory"},
        {"no/such/dir/a.png",
         "cannot write \"no/such/dir/a.png\": directory \"no/such/dir\" "
         "does not exist"},
        {"file.txt/a.png", "cannot write \"file.txt/a.png\": \"file.txt\" is not a directory"},
        {"outdir",
         "cannot write \"outdir\": the name has no extension to choose the image "
         "format; image formats are: .png, .ppm, .pfm, .exr"},
        {"out.gif", "cannot write \"out.gif\": unknown image format \".gif\""},
    };
    for (const auto& [output, message] : expected) {
        const Outcome r = run_glint("render nowhere.yaml -q -o " + output);
        EXPECT_EQ(r.exit_code, 2) << output;
        EXPECT_EQ(r.err.find("glint: error: " + message), 0u) << r.err;
    }
    const Outcome stats = run_glint("render nowhere.yaml -q -o a.png --stats no/s.json");
    EXPECT_EQ(stats.exit_code, 2);
    EXPECT_NE(stats.err.find("cannot write \"no/s.json\": directory \"no\" does not exist"),
              std::string::npos)
        << stats.err;
    EXPECT_TRUE(fs::is_directory(dir_ / "taken.png"));  // survives
    for (const auto& entry : fs::directory_iterator(dir_)) {
        const std::string name = entry.path().filename().string();
        EXPECT_TRUE(name == "taken.png" || name == "file.txt" || name == "stdout.txt" ||
                    name == "stderr.txt")
            << name;
    }
}

TEST_F(Cli, ReadOnlyOutputDirectoryIsRejectedBeforeLoading) {
    fs::create_directories(dir_ / "locked");
    fs::permissions(dir_ / "locked", fs::perms::owner_read | fs::perms::owner_exec);
    const bool writable = access((dir_ / "locked").c_str(), W_OK) == 0;
    const Outcome r = run_glint("render nowhere.yaml -q -o locked/a.png");
    fs::permissions(dir_ / "locked", fs::perms::owner_all);
    if (writable) GTEST_SKIP() << "permissions do not bind here (running as root)";
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("cannot write \"locked/a.png\": directory \"locked\" is not writable"),
              std::string::npos)
        << r.err;
}

// A disk that fills up while the image is written, made by a file-size limit (dash's `ulimit
// -f` counts blocks of 512 bytes: 8 KiB, less than the 64 x 48 PPM): a clear error, the
// previous image as it was, no temporary left behind.
TEST_F(Cli, AFullDiskIsReportedAndLeavesThePreviousImage) {
    std::ofstream(dir_ / "out.ppm") << "the previous image";
    const Outcome r = run_glint("render " + scene("showcase.yaml") + " --width 64 -q -o out.ppm",
                                "ulimit -f 16 && ");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("glint: error: out.ppm: "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("File too large"), std::string::npos) << r.err;
    EXPECT_EQ(slurp(dir_ / "out.ppm"), "the previous image");
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir_))
        names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    EXPECT_EQ(names, (std::vector<std::string>{"out.ppm", "stderr.txt", "stdout.txt"}));
}

// The same for the statistics: a 15-byte image and some 800 bytes of JSON (it names the scene
// and the image, given long names here) under a limit of 512 bytes.
TEST_F(Cli, AFullDiskIsReportedAndLeavesThePreviousStatistics) {
    const std::string scene_name = std::string(200, 's') + ".yaml",
                      image_name = std::string(200, 'i') + ".ppm";
    fs::copy_file(std::string(GLINT_SOURCE_DIR) + "/scenes/showcase.yaml", dir_ / scene_name);
    std::ofstream(dir_ / "stats.json") << "the previous statistics";
    const Outcome r = run_glint("render " + scene_name + " --width 1 --height 1 -q -o " +
                                    image_name + " --stats stats.json",
                                "ulimit -f 1 && ");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("glint: error: stats.json: "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("File too large"), std::string::npos) << r.err;
    EXPECT_EQ(slurp(dir_ / "stats.json"), "the previous statistics");
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir_))
        names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    EXPECT_EQ(names, (std::vector<std::string>{image_name, scene_name, "stats.json", "stderr.txt",
                                               "stdout.txt"}));
}

// Ctrl-C twice in the middle of a render that would replace a good image: the image stays as it
// was, byte for byte, and the finished tiles go to the .partial sibling. The signal is sent
// once glint reports progress (its handler is in place by then). A machine fast enough to
// finish the render first leaves nothing to check, and the test is skipped.
TEST_F(Cli, InterruptedRenderLeavesTheTargetAloneAndWritesAPartialImage) {
    ASSERT_EQ(run_glint("render " + scene("showcase.yaml") + " --width 16 -q -o out.png").exit_code,
              0);
    const std::string good = slurp(dir_ / "out.png");
    ASSERT_FALSE(good.empty());

    // Held after 3 of the 80 tiles of the first of two passes: Ctrl-C always finds it running.
    const pid_t pid =
        spawn_glint({"render", std::string(GLINT_SOURCE_DIR) + "/scenes/showcase.yaml", "--width",
                     "160", "--spp", "25", "--threads", "1", "-o", (dir_ / "out.png").string()},
                    hold_after(3));
    ASSERT_GT(pid, 0);
    int status = 0;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(5);
    while (!holding()) {
        ASSERT_NE(waitpid(pid, &status, WNOHANG), pid)
            << "glint ended before it held: " << slurp(dir_ / "stderr.txt");
        ASSERT_LT(std::chrono::steady_clock::now(), deadline) << "glint did not hold";
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    // Twice: the first would finish the pass in flight. Apart: a signal sent while the same one
    // is pending is lost.
    ASSERT_EQ(kill(pid, SIGINT), 0);
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    kill(pid, SIGINT);  // it may have ended by now
    waitpid(pid, &status, 0);

    const std::string err = slurp(dir_ / "stderr.txt");
    ASSERT_TRUE(WIFEXITED(status)) << err;
    EXPECT_EQ(WEXITSTATUS(status), 130) << err;
    EXPECT_TRUE(slurp(dir_ / "out.png") == good) << "the earlier image was changed";
    EXPECT_NE(err.find("out.partial.png"), std::string::npos) << err;
    const Image partial = read_image(dir_ / "out.partial.png");
    EXPECT_EQ(partial.width, 160);
    EXPECT_EQ(partial.height, 120);
    for (const auto& entry : fs::directory_iterator(dir_))
        EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos) << entry.path();
}

// Interrupt and resume end to end. A distributed render of 16 passes, a few seconds long, is
// interrupted once its first progress line shows (by one Ctrl-C, two, or SIGTERM), leaves the
// image so far and a resume file but not the target, and --resume finishes it to the image of an
// uninterrupted render, byte for byte; a resume file of other settings is refused; a render
// killed outright resumes from its last checkpoint.
TEST_F(Cli, ExplainWritesAPixelsRayTreeAsTextJsonAndDot) {
    // Through the glass sphere of the showcase: eye, reflected and refracted rays.
    const std::string base = "explain " + scene("showcase.yaml") + " --pixel 440,330";
    const Outcome text = run_glint(base);
    ASSERT_EQ(text.exit_code, 0) << text.err;
    for (const char* expected :
         {"pixel (440, 330), sample 0, seed 0, the whitted integrator",
          "(the tree's terms give it to the last bit)", "eye ray from (0, 2.2, -8)",
          "hits object 1 (sphere), material \"glass\"", "Snell: n1 = 1, n2 = 1.5",
          "refracted ray from", "point light 0: L ", "is below the minimum weight"})
        EXPECT_NE(text.out.find(expected), std::string::npos) << expected << "\n" << text.out;

    const Outcome json = run_glint(base + " --format json --sample 4 --seed 7");
    ASSERT_EQ(json.exit_code, 0) << json.err;
    EXPECT_EQ(json.out.rfind("{\"format\": \"glint-ray-tree\", \"version\": 1", 0), 0u) << json.out;
    EXPECT_NE(json.out.find("\"sample\": 4, \"seed\": 7"), std::string::npos);

    ASSERT_EQ(run_glint(base + " --format dot -o tree.dot").exit_code, 0);
    EXPECT_EQ(slurp(dir_ / "tree.dot").rfind("digraph ray_tree {", 0), 0u);
    // Graphviz draws it (install-deps installs it), a node for each ray and light.
    const std::string svg = (dir_ / "tree.svg").string();
    ASSERT_EQ(
        std::system(("dot -Tsvg '" + (dir_ / "tree.dot").string() + "' -o '" + svg + "'").c_str()),
        0);
    EXPECT_NE(slurp(svg).find("refracted ray"), std::string::npos);
}

TEST_F(Cli, ExplainRefusesAPixelOrSampleOutsideTheImage) {
    const std::string base = "explain " + scene("showcase.yaml");
    for (const auto& [options, message] : std::vector<std::pair<std::string, std::string>>{
             {"--pixel 5", "--pixel: expected X,Y, two whole numbers from 0"},
             {"--pixel 5,-1", "--pixel: expected X,Y"},
             {"--pixel 800,10", "pixel (800, 10) is outside the image of 800x600 pixels"},
             {"--pixel 10,10 --width 8", "pixel (10, 10) is outside the image of 8x6 pixels"},
             {"--pixel 1,1 --sample 9", "sample 9 of a pixel of 9 samples"},
             {"--pixel 1,1 --format svg", "--format"}}) {
        const Outcome r = run_glint(base + " " + options);
        EXPECT_EQ(r.exit_code, 2) << options;
        EXPECT_NE(r.err.find(message), std::string::npos) << options << ": " << r.err;
    }
    EXPECT_EQ(run_glint("explain nowhere.yaml --pixel 1,1").exit_code, 2);
}

// A sample over the film's limit is left out of the image and reported with the command that
// replays it; that command explains where its value came from.
TEST_F(Cli, ABadSampleCanBeReplayedWithExplain) {
    write_scene("hot.yaml", R"(image: {width: 16, height: 12, samples: 4}
camera: {from: [0, 0, -5], at: [0, 0, 0], fov: 40}
materials:
  hot: {emission: [3e9, 3e9, 3e9]}
objects:
  - {type: sphere, center: [0, 0, 0], radius: 1, material: hot}
)");
    const Outcome render = run_glint("render hot.yaml -q --seed 3 --spp 4 --sampler jittered");
    ASSERT_EQ(render.exit_code, 0) << render.err;
    const std::string prefix = "glint: to see how it was computed: glint ";
    const std::size_t at = render.err.find(prefix);
    ASSERT_NE(at, std::string::npos) << render.err;
    const std::string replay =
        render.err.substr(at + prefix.size(), render.err.find('\n', at) - at - prefix.size());
    EXPECT_NE(replay.find("--seed 3 --spp 4 --sampler jittered"), std::string::npos) << replay;
    const Outcome explained = run_glint(replay);
    ASSERT_EQ(explained.exit_code, 0) << replay << ": " << explained.err;
    EXPECT_NE(explained.out.find("emission (3e+09, 3e+09, 3e+09)"), std::string::npos)
        << explained.out;
    EXPECT_NE(explained.out.find("sample colour (3e+09, 3e+09, 3e+09)"), std::string::npos)
        << explained.out;

    // A frame of an animation: replayed at that frame.
    write_scene("hot-frames.yaml", "animation: {frames: 3}\n" + slurp(dir_ / "hot.yaml"));
    const Outcome frame = run_glint("render hot-frames.yaml -q --seed 3 --frames 2 -o 'hot.#.png'");
    ASSERT_EQ(frame.exit_code, 0) << frame.err;
    const std::size_t frame_at = frame.err.find(prefix);
    ASSERT_NE(frame_at, std::string::npos) << frame.err;
    const std::string frame_replay = frame.err.substr(
        frame_at + prefix.size(), frame.err.find('\n', frame_at) - frame_at - prefix.size());
    EXPECT_NE(frame_replay.find("--frame 2"), std::string::npos) << frame_replay;
    EXPECT_EQ(run_glint(frame_replay).exit_code, 0) << frame_replay;
}

// Output variables: PNG pictures beside a PNG image, layers of an EXR one; bad lists and
// combinations are usage errors that write nothing.
TEST_F(Cli, AovsArePngsBesideTheImageOrLayersOfItsExr) {
    const std::string scene = std::string(GLINT_SOURCE_DIR) + "/scenes/showcase.yaml";
    const Outcome png =
        run_glint("render '" + scene + "' -q --width 40 --height 30 -o out.png --aov depth,ids");
    ASSERT_EQ(png.exit_code, 0) << png.err;
    for (const char* name : {"out.png", "out.depth.png", "out.object.png", "out.material.png"})
        EXPECT_TRUE(fs::exists(dir_ / name)) << name;
    const Image depth = read_image(dir_ / "out.depth.png");
    EXPECT_EQ(depth.width, 40);
    EXPECT_EQ(depth.height, 30 + 13);  // the legend's strip below

    const Outcome exr = run_glint("render '" + scene +
                                  "' -q --width 40 --height 30 -o out.exr --aov normal,samples");
    ASSERT_EQ(exr.exit_code, 0) << exr.err;
    const std::string bytes = slurp(dir_ / "out.exr");
    for (const char* channel : {"normal.X", "normal.Y", "normal.Z", "samples.Y"})
        EXPECT_NE(bytes.find(channel), std::string::npos) << channel;
    EXPECT_FALSE(fs::exists(dir_ / "out.normal.png"));
}

TEST_F(Cli, BadAovListsAreUsageErrors) {
    const std::string scene = std::string(GLINT_SOURCE_DIR) + "/scenes/showcase.yaml";
    const Outcome unknown = run_glint("render '" + scene + "' -q -o out.png --aov depth,colour");
    EXPECT_EQ(unknown.exit_code, 2);
    EXPECT_NE(unknown.err.find("--aov: unknown output variable 'colour'"), std::string::npos)
        << unknown.err;
    const Outcome resumed =
        run_glint("render '" + scene + "' -q -o out.png --aov depth --checkpoint 5");
    EXPECT_EQ(resumed.exit_code, 2);
    EXPECT_NE(resumed.err.find("cannot be combined with --resume, --checkpoint or --part"),
              std::string::npos)
        << resumed.err;
    EXPECT_FALSE(fs::exists(dir_ / "out.png"));
}

// Samples per pixel of the renders these tests stop: 3 passes of 16, each of 40 tiles.
constexpr int kResumeSpp = 48;
constexpr int kResumeTilesPerPass = 40;

class Resume : public Cli {
protected:
    std::vector<std::string> args(const std::vector<std::string>& more = {},
                                  const std::string& output = "out.png") const {
        std::vector<std::string> a = {"render",  scene_.string(),
                                      "--width", "120",
                                      "--spp",   std::to_string(kResumeSpp),
                                      "--seed",  "3",
                                      "-o",      (dir_ / output).string()};
        a.insert(a.end(), more.begin(), more.end());
        return a;
    }
    static std::string joined(const std::vector<std::string>& a) {
        std::string line;
        for (const std::string& arg : a) line += "'" + arg + "' ";
        return line;
    }
    // Starts the render held after `hold` tiles (apps/glint/test_hold.h), waits until it
    // holds, sends the signals; the exit status, or -1 (a failure) when the render ended before
    // it held.
    int interrupt(const std::vector<int>& signals, const std::vector<std::string>& more,
                  int hold = kResumeTilesPerPass / 4) const {
        const pid_t pid = spawn_glint(args(more), hold_after(hold));
        EXPECT_GT(pid, 0);
        int status = 0;
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(5);
        while (!holding()) {
            if (waitpid(pid, &status, WNOHANG) == pid) {
                ADD_FAILURE() << "glint ended before it held: " << slurp(dir_ / "stderr.txt");
                return -1;
            }
            if (std::chrono::steady_clock::now() > deadline) {
                kill(pid, SIGKILL);
                waitpid(pid, &status, 0);
                ADD_FAILURE() << "glint did not hold in five minutes";
                return -1;
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        }
        for (const int signal : signals) {
            kill(pid, signal);
            // A signal sent while the same one is pending is lost.
            std::this_thread::sleep_for(std::chrono::milliseconds(200));
        }
        waitpid(pid, &status, 0);
        if (WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL) return -SIGKILL;
        return WIFEXITED(status) ? WEXITSTATUS(status) : -2;
    }

    fs::path scene_ = fs::path(GLINT_SOURCE_DIR) / "scenes/distributed-showcase.yaml";
};

TEST_F(Resume, InterruptedRenderResumesToTheUninterruptedImage) {
    ASSERT_EQ(run_glint(joined(args({"-q"}, "reference.png"))).exit_code, 0);
    const std::string reference = slurp(dir_ / "reference.png");
    struct Stop {
        const char* name;
        std::vector<int> signals;
    };
    for (const Stop& stop : {Stop{"Ctrl-C", {SIGINT}}, Stop{"Ctrl-C twice", {SIGINT, SIGINT}},
                             Stop{"SIGTERM", {SIGTERM}}}) {
        SCOPED_TRACE(stop.name);
        const int status = interrupt(stop.signals, {});
        const std::string err = slurp(dir_ / "stderr.txt");
        ASSERT_EQ(status, 130) << err;
        EXPECT_NE(err.find("--resume"), std::string::npos) << err;
        EXPECT_FALSE(fs::exists(dir_ / "out.png"));
        ASSERT_TRUE(fs::exists(dir_ / "out.png.resume"));
        const Image partial = read_image(dir_ / "out.partial.png");
        EXPECT_EQ(partial.width, 120);

        const Outcome resumed = run_glint(joined(args({"--resume", "-q"})));
        ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
        EXPECT_TRUE(slurp(dir_ / "out.png") == reference) << "not the uninterrupted image";
        EXPECT_FALSE(fs::exists(dir_ / "out.png.resume"));
        EXPECT_FALSE(fs::exists(dir_ / "out.partial.png"));
        fs::remove(dir_ / "out.png");
    }
}

TEST_F(Resume, ResumeFileOfOtherSettingsIsRefusedAndAMissingOneIsAnError) {
    const Outcome missing = run_glint(joined(args({"--resume"})));
    EXPECT_EQ(missing.exit_code, 2);
    EXPECT_NE(missing.err.find("out.png.resume\": there is no such file"), std::string::npos)
        << missing.err;
    ASSERT_EQ(interrupt({SIGINT}, {}), 130) << slurp(dir_ / "stderr.txt");
    const std::string saved = slurp(dir_ / "out.png.resume");
    for (const auto& [option, message] :
         {std::pair<std::vector<std::string>, std::string>{{"--seed", "4"}, "for seed 3, not 4"},
          {{"--spp", "128"}, "for " + std::to_string(kResumeSpp) + " samples per pixel, not 128"},
          {{"--width", "100"}, "for an image of 120x68, not 100x56"},
          {{"--filter", "box"}, "not a box filter"}}) {
        std::vector<std::string> changed = args({"--resume"});
        const auto at = std::find(changed.begin(), changed.end(), option[0]);
        if (at != changed.end())
            *(at + 1) = option[1];
        else
            changed.insert(changed.end(), option.begin(), option.end());
        const Outcome refused = run_glint(joined(changed));
        EXPECT_EQ(refused.exit_code, 2) << option[0];
        EXPECT_NE(refused.err.find(message), std::string::npos) << refused.err;
        EXPECT_FALSE(fs::exists(dir_ / "out.png")) << option[0];
        EXPECT_TRUE(slurp(dir_ / "out.png.resume") == saved) << option[0];
    }
    // The accelerating structure and the thread count do not change the image: no refusal.
    EXPECT_EQ(run_glint(joined(args({"--resume", "-q", "--accel", "kdtree", "--threads", "1"})))
                  .exit_code,
              0);
}

// The files a scene reads are checked as its own is: a texture changed since the interruption
// refuses the resume file, naming the texture; put back, the render resumes.
TEST_F(Resume, ATextureChangedSinceTheInterruptionIsNamed) {
    fs::copy_file(fs::path(GLINT_SOURCE_DIR) / "tests/data/meshes/spot_texture.png",
                  dir_ / "spot.png");
    std::string text = slurp(scene_);
    text.replace(text.find("materials:\n"), 11,
                 "materials:\n  spot: {color: {type: image, file: spot.png}, ka: 0.3, kd: 0.7}\n");
    text += "  - {type: sphere, center: [0, 3, 2], radius: 0.8, material: spot}\n";
    scene_ = dir_ / "textured.yaml";
    write_scene("textured.yaml", text);
    ASSERT_EQ(interrupt({SIGINT}, {}), 130) << slurp(dir_ / "stderr.txt");
    const std::string texture = slurp(dir_ / "spot.png");
    std::ofstream(dir_ / "spot.png", std::ios::app) << "a changed texture";
    const Outcome refused = run_glint(joined(args({"--resume", "-q"})));
    EXPECT_EQ(refused.exit_code, 2);
    EXPECT_NE(refused.err.find("the resume file was written before " +
                               fs::canonical(dir_ / "spot.png").string() + " changed"),
              std::string::npos)
        << refused.err;
    std::ofstream(dir_ / "spot.png", std::ios::binary | std::ios::trunc) << texture;
    EXPECT_EQ(run_glint(joined(args({"--resume", "-q"}))).exit_code, 0);
}

TEST_F(Resume, CheckpointsLetARenderKilledOutrightResume) {
    ASSERT_EQ(run_glint(joined(args({"-q"}, "reference.png"))).exit_code, 0);
    // A checkpoint after every pass (1e-9 minutes: any time at all); SIGKILL in the second pass,
    // after the first pass's checkpoint.
    ASSERT_EQ(interrupt({SIGKILL}, {"--checkpoint", "1e-9", "-q"}, kResumeTilesPerPass + 5),
              -SIGKILL);
    EXPECT_TRUE(fs::exists(dir_ / "out.png.resume"));
    EXPECT_FALSE(fs::exists(dir_ / "out.png"));
    EXPECT_TRUE(fs::exists(dir_ / "out.partial.png"));
    const Outcome resumed = run_glint(joined(args({"--resume", "-q"})));
    ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
    EXPECT_TRUE(slurp(dir_ / "out.png") == slurp(dir_ / "reference.png"));
}

TEST_F(Resume, OnePassRenderStopsAtTheFirstCtrlCAndResumesExactly) {
    // Whitted's single sample: one pass, which the first Ctrl-C does not wait for.
    const std::vector<std::string> whitted = {
        "render",    std::string(GLINT_SOURCE_DIR) + "/scenes/showcase.yaml",
        "--width",   "320",
        "--threads", "1"};
    std::vector<std::string> reference = whitted, resume = whitted;
    reference.insert(reference.end(), {"-q", "-o", (dir_ / "reference.png").string()});
    resume.insert(resume.end(), {"-q", "--resume", "-o", (dir_ / "out.png").string()});
    ASSERT_EQ(run_glint(joined(reference)).exit_code, 0);
    std::vector<std::string> run = whitted;
    run.insert(run.end(), {"-o", (dir_ / "out.png").string()});
    // Held after 10 of its 300 tiles.
    const pid_t pid = spawn_glint(run, hold_after(10));
    ASSERT_GT(pid, 0);
    int status = 0;
    while (!holding()) {
        ASSERT_NE(waitpid(pid, &status, WNOHANG), pid)
            << "glint ended before it held: " << slurp(dir_ / "stderr.txt");
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    kill(pid, SIGINT);
    waitpid(pid, &status, 0);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 130) << slurp(dir_ / "stderr.txt");
    EXPECT_NE(slurp(dir_ / "stderr.txt").find("interrupted in the first pass:"), std::string::npos)
        << slurp(dir_ / "stderr.txt");
    const Outcome resumed = run_glint(joined(resume));
    ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
    EXPECT_TRUE(slurp(dir_ / "out.png") == slurp(dir_ / "reference.png"));
}

TEST_F(Resume, TheTestHoldTakesAWholeNumberOfTiles) {
    for (const char* bad : {"0", "-3", "many", "4x", ""}) {
        const Outcome r =
            run_glint(joined(args({"-q"})),
                      std::string("export GLINT_TEST_HOLD_AFTER_TILES='") + bad + "' && ");
        EXPECT_EQ(r.exit_code, 2) << bad;
        EXPECT_NE(r.err.find("GLINT_TEST_HOLD_AFTER_TILES must be a whole number of tiles"),
                  std::string::npos)
            << r.err;
    }
}

TEST_F(Resume, CheckpointMustBeAPositiveNumberOfMinutes) {
    for (const char* bad : {"0", "-1", "soon"})
        EXPECT_EQ(run_glint(joined(args({"--checkpoint", bad}))).exit_code, 2) << bad;
}

}  // namespace
}  // namespace glint
