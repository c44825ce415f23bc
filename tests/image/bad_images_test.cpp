// Malformed image files in tests/data/bad_images/, listed in its expected.txt with text that the
// error must contain: textures (PNG, JPEG, Radiance HDR, TGA, BMP) as scenes load them, and the
// formats glint itself reads back (PPM, PFM, OpenEXR). Each must fail with an ImageError that
// names the file; none may crash, hang or load.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include "glint/image/image_error.h"
#include "glint/image/image_io.h"
#include "glint/image/texture_file.h"

namespace glint {
namespace {

const std::filesystem::path kBadDir =
    std::filesystem::path(GLINT_SOURCE_DIR) / "tests/data/bad_images";

struct Expectation {
    std::string file;
    std::string message;  // contained in the error's message
};

// Lines "FILE | MESSAGE"; '#' starts a comment line.
std::vector<Expectation> read_expectations() {
    std::ifstream in(kBadDir / "expected.txt");
    std::vector<Expectation> out;
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line.starts_with("#")) continue;
        const auto bar = line.find(" | ");
        EXPECT_NE(bar, std::string::npos) << "malformed line: " << line;
        if (bar == std::string::npos) continue;
        out.push_back({line.substr(0, bar), line.substr(bar + 3)});
    }
    return out;
}

// Textures go through the texture reader; the formats glint writes, through its own readers.
Image load(const std::filesystem::path& file) {
    const std::string ext = file.extension().string();
    if (ext == ".ppm" || ext == ".pfm" || ext == ".exr") return read_image(file);
    return load_texture_image(file);
}

TEST(BadImages, EveryFileIsListedAndEveryFormatIsThere) {
    std::set<std::string> listed, formats;
    for (const Expectation& e : read_expectations()) listed.insert(e.file);
    for (const auto& entry : std::filesystem::directory_iterator(kBadDir)) {
        const std::string name = entry.path().filename().string();
        if (name == "expected.txt" || name == "README.md") continue;
        EXPECT_TRUE(listed.count(name)) << name << " is not in expected.txt";
        formats.insert(entry.path().extension().string());
    }
    EXPECT_EQ(formats, (std::set<std::string>{".bmp", ".exr", ".hdr", ".jpg", ".pfm", ".png",
                                              ".ppm", ".tga"}));
}

TEST(BadImages, EachGivesItsErrorNamingTheFile) {
    for (const Expectation& e : read_expectations()) {
        SCOPED_TRACE(e.file);
        const auto path = kBadDir / e.file;
        try {
            load(path);
            ADD_FAILURE() << "loaded without an error";
        } catch (const ImageError& error) {
            EXPECT_EQ(error.file, path) << error.what();
            EXPECT_NE(std::string(error.what()).find(e.message), std::string::npos)
                << "message: " << error.what() << "\nexpected to contain: " << e.message;
        }
    }
}

}  // namespace
}  // namespace glint
