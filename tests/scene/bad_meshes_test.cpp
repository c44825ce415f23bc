// Malformed mesh files in tests/data/bad_meshes/, listed in its expected.txt with the error each
// must give: where (file:line:col, or the file alone) and text the message must contain.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "glint/scene/mesh/model_loader.h"
#include "glint/scene/scene_error.h"

namespace glint {
namespace {

const std::filesystem::path kBadDir =
    std::filesystem::path(GLINT_SOURCE_DIR) / "tests/data/bad_meshes";

struct Expectation {
    std::string file;     // the file to load
    std::string at_file;  // the file the error names (an MTL file may be at fault)
    int line = 0;         // 0: no line
    int column = 0;
    std::string message;  // contained in the error's message
};

std::string trim(std::string s) {
    s.erase(0, s.find_first_not_of(" \t"));
    s.erase(s.find_last_not_of(" \t\r") + 1);
    return s;
}

// Lines "FILE | AT_FILE[:LINE:COL] | MESSAGE"; '#' starts a comment line.
std::vector<Expectation> read_expectations() {
    std::ifstream in(kBadDir / "expected.txt");
    std::vector<Expectation> out;
    std::string line;
    while (std::getline(in, line)) {
        if (trim(line).empty() || line.starts_with("#")) continue;
        const auto bar1 = line.find(" | "), bar2 = line.find(" | ", bar1 + 3);
        EXPECT_NE(bar2, std::string::npos) << "malformed line: " << line;
        if (bar2 == std::string::npos) continue;
        Expectation e;
        e.file = trim(line.substr(0, bar1));
        std::string at = trim(line.substr(bar1 + 3, bar2 - bar1 - 3));
        e.message = trim(line.substr(bar2 + 3));
        const auto colon = at.find(':');
        e.at_file = at.substr(0, colon);
        if (colon != std::string::npos) {
            std::istringstream numbers(at.substr(colon + 1));
            char c = 0;
            numbers >> e.line >> c >> e.column;
        }
        out.push_back(e);
    }
    return out;
}

TEST(BadMeshes, ThereAreAtLeast15AndEveryFileIsListed) {
    const auto expectations = read_expectations();
    EXPECT_GE(expectations.size(), 15u);
    for (const auto& entry : std::filesystem::directory_iterator(kBadDir)) {
        const std::string name = entry.path().filename().string();
        const std::string ext = entry.path().extension().string();
        if (name == "expected.txt" || name == "README.md" || ext == ".bin" || ext == ".mtl") {
            continue;
        }
        const bool listed = std::any_of(expectations.begin(), expectations.end(),
                                        [&](const Expectation& e) { return e.file == name; });
        EXPECT_TRUE(listed) << name << " is not in expected.txt";
    }
}

TEST(BadMeshes, EachGivesItsStatedError) {
    for (const Expectation& expected : read_expectations()) {
        SCOPED_TRACE(expected.file);
        try {
            load_model(kBadDir / expected.file);
            ADD_FAILURE() << "loaded without error";
        } catch (const SceneError& e) {
            const std::string shown = format_scene_error(e);
            EXPECT_EQ(e.location().file, (kBadDir / expected.at_file).string()) << shown;
            EXPECT_EQ(e.location().line, expected.line) << shown;
            EXPECT_EQ(e.location().column, expected.column) << shown;
            EXPECT_NE(e.message().find(expected.message), std::string::npos) << shown;
            if (e.location().line > 0) {
                EXPECT_FALSE(e.source_line().empty()) << shown;
            }
            // The file at fault is always named where the user looks first.
            EXPECT_TRUE(shown.starts_with((kBadDir / expected.at_file).string())) << shown;
        } catch (const std::exception& e) {
            ADD_FAILURE() << "threw something other than a SceneError: " << e.what();
        }
    }
}

}  // namespace
}  // namespace glint
