// Every file of Haines' Standard Procedural Databases in ../shared/data/spd (plain and gzipped)
// parses, and gives the text size and primitive counts of that folder's README table. Skips
// when the folder is absent (it is not part of the repository).
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>

#include "glint/scene/gzip_file.h"
#include "glint/scene/nff/nff_parser.h"

namespace glint {
namespace {

const std::filesystem::path kSpdDir = std::filesystem::path(GLINT_SOURCE_DIR "/../shared/data/spd");

struct SpdFile {
    const char* name;
    std::uint64_t bytes;  // uncompressed
    std::size_t spheres, cones, polygons, patches, lights;
    int resolution;
};

void PrintTo(const SpdFile& file, std::ostream* os) { *os << file.name; }

// From the README's table ("Counts come from parsing the files").
constexpr SpdFile kFiles[] = {
    {"balls.nff", 305317, 7381, 0, 1, 0, 3, 512},
    {"gears.nff", 1335003, 0, 0, 9345, 0, 5, 512},
    {"jacks.nff", 524, 6, 3, 0, 0, 1, 256},
    {"lattice.nff", 767285, 2197, 6084, 0, 0, 6, 512},
    {"mount.nff", 632253, 4, 0, 8192, 0, 1, 512},
    {"rings.nff", 421988, 4200, 4200, 1, 0, 3, 512},
    {"sample.nff", 146326, 0, 1, 16, 864, 1, 512},
    {"shells.nff", 233896, 5761, 0, 0, 0, 1, 512},
    {"sombrero.nff", 155626, 0, 0, 1922, 0, 1, 512},
    {"teapot.nff", 360747, 0, 0, 36, 2256, 2, 512},
    {"tetra.nff", 255616, 0, 0, 4096, 0, 1, 512},
    {"tree.nff", 475128, 4095, 4095, 1, 0, 7, 512},
    {"teapot-s12.nff.gz", 1508322, 0, 0, 144, 9120, 2, 512},
    {"balls-s5.nff.gz", 2753315, 66430, 0, 1, 0, 3, 512},
    {"balls-s6.nff.gz", 25313775, 597871, 0, 1, 0, 3, 512},
    {"gears-s8.nff.gz", 11422226, 0, 0, 74753, 0, 5, 512},
    {"gears-s10.nff.gz", 20883022, 0, 0, 146001, 0, 5, 512},
    {"lattice-s25.nff.gz", 5127377, 17576, 50700, 0, 0, 6, 512},
    {"lattice-s40.nff.gz", 22724847, 68921, 201720, 0, 0, 6, 512},
    {"mount-s8.nff.gz", 11490882, 4, 0, 131072, 0, 1, 512},
    {"mount-s9.nff.gz", 46850433, 4, 0, 524288, 0, 1, 512},
    {"rings-s15.nff.gz", 3714838, 37200, 37200, 1, 0, 3, 512},
    {"rings-s20.nff.gz", 8589984, 86100, 86100, 1, 0, 3, 512},
    {"teapot-s30.nff.gz", 9629864, 0, 0, 900, 57360, 2, 512},
    {"teapot-s60.nff.gz", 38990757, 0, 0, 3600, 229920, 2, 512},
    {"tetra-s8.nff.gz", 5273536, 0, 0, 65536, 0, 1, 512},
    {"tetra-s9.nff.gz", 22388416, 0, 0, 262144, 0, 1, 512},
    {"tetra-s10.nff.gz", 92216512, 0, 0, 1048576, 0, 1, 512},
    {"tree-s14.nff.gz", 3879724, 32767, 32767, 1, 0, 7, 512},
    {"tree-s16.nff.gz", 15564574, 131071, 131071, 1, 0, 7, 512},
};

class SpdParse : public ::testing::TestWithParam<SpdFile> {};

TEST_P(SpdParse, GivesTheCountsOfTheReadme) {
    if (!std::filesystem::is_directory(kSpdDir)) GTEST_SKIP() << kSpdDir << " is absent";
    const SpdFile& expected = GetParam();
    const auto path = kSpdDir / expected.name;
    ASSERT_TRUE(std::filesystem::exists(path)) << path;

    const auto start = std::chrono::steady_clock::now();
    const std::string text = read_maybe_gzipped(path, kMaxNffFileBytes);
    const auto read = std::chrono::steady_clock::now();
    EXPECT_EQ(text.size(), expected.bytes);
    NffScene scene;
    try {
        scene = parse_nff(text, path.string());
    } catch (const SceneError& e) {
        FAIL() << format_scene_error(e);
    }
    const auto parsed = std::chrono::steady_clock::now();
    using ms = std::chrono::duration<double, std::milli>;
    std::printf("%s: %.1f MB, read in %.0f ms, parsed in %.0f ms\n", expected.name,
                text.size() / 1e6, ms(read - start).count(), ms(parsed - read).count());

    std::size_t spheres = 0, cones = 0, polygons = 0, patches = 0;
    for (const NffObject& o : scene.objects) {
        ASSERT_LT(o.material, scene.materials.size());
        spheres += std::holds_alternative<NffSphere>(o.primitive);
        cones += std::holds_alternative<NffCone>(o.primitive);
        polygons += std::holds_alternative<NffPolygon>(o.primitive);
        patches += std::holds_alternative<NffPatch>(o.primitive);
    }
    EXPECT_EQ(spheres, expected.spheres);
    EXPECT_EQ(cones, expected.cones);
    EXPECT_EQ(polygons, expected.polygons);
    EXPECT_EQ(patches, expected.patches);
    EXPECT_EQ(scene.lights.size(), expected.lights);
    const NffView& view = require_view(scene);
    EXPECT_EQ(view.width, expected.resolution);
    EXPECT_EQ(view.height, expected.resolution);
    EXPECT_TRUE(scene.background);
}

INSTANTIATE_TEST_SUITE_P(Spd, SpdParse, ::testing::ValuesIn(kFiles),
                         [](const ::testing::TestParamInfo<SpdFile>& param) {
                             std::string name = param.param.name;
                             for (char& c : name) {
                                 if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                             }
                             return name;
                         });

}  // namespace
}  // namespace glint
