// Malformed scenes in tests/scene/bad/, one file each. A file's first line states the error it must
// give, `# error: LINE:COL: MESSAGE` (0:0 for an error without a location), and any further
// `# note: TEXT` lines give text that must appear in one of its notes.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "glint/scene/yaml/yaml_scene_loader.h"

namespace glint {
namespace {

const std::filesystem::path kBadDir = std::filesystem::path(GLINT_SOURCE_DIR) / "tests/scene/bad";

struct Expectation {
    int line = -1;
    int column = -1;
    std::string message;
    std::vector<std::string> notes;
};

// Nothing when the header is malformed; the test then fails for that file.
std::optional<Expectation> read_expectation(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::string line;
    Expectation e;
    if (!std::getline(in, line)) return std::nullopt;
    const std::string prefix = "# error: ";
    if (!line.starts_with(prefix)) return std::nullopt;
    std::istringstream header(line.substr(prefix.size()));
    char colon1 = 0, colon2 = 0;
    if (!(header >> e.line >> colon1 >> e.column >> colon2) || colon1 != ':' || colon2 != ':') {
        return std::nullopt;
    }
    std::getline(header >> std::ws, e.message);
    while (std::getline(in, line) && line.starts_with("# note: ")) {
        e.notes.push_back(line.substr(8));
    }
    return e;
}

std::vector<std::filesystem::path> bad_scene_files() {
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(kBadDir)) {
        if (entry.path().extension() == ".yaml") files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end());
    return files;
}

TEST(BadScenes, ThereAreAtLeast25) { EXPECT_GE(bad_scene_files().size(), 25u); }

TEST(BadScenes, EachGivesItsStatedError) {
    for (const auto& file : bad_scene_files()) {
        SCOPED_TRACE(file.filename().string());
        const auto expected = read_expectation(file);
        ASSERT_TRUE(expected) << "first line must be '# error: LINE:COL: MESSAGE'";
        try {
            load_yaml_scene(file);
            ADD_FAILURE() << "loaded without error";
        } catch (const SceneError& e) {
            const std::string shown = format_scene_error(e);
            EXPECT_EQ(e.location().file, file.string());
            EXPECT_EQ(e.location().line, expected->line) << shown;
            EXPECT_EQ(e.location().column, expected->column) << shown;
            EXPECT_EQ(e.message(), expected->message) << shown;
            for (const std::string& note : expected->notes) {
                const bool found = std::any_of(
                    e.notes().begin(), e.notes().end(),
                    [&](const std::string& n) { return n.find(note) != std::string::npos; });
                EXPECT_TRUE(found) << "no note contains: " << note << "\n" << shown;
            }
            // A located error quotes its line, so the user sees it without opening the file.
            if (e.location().line > 0) {
                EXPECT_FALSE(e.source_line().empty()) << shown;
            }
        } catch (const std::exception& e) {
            ADD_FAILURE() << "threw something other than a SceneError: " << e.what();
        }
    }
}

}  // namespace
}  // namespace glint
