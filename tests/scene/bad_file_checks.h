// Malformed input files, one per kind of error, checked data-driven: a file's first line states
// the error it must give, `# error: LINE:COL: MESSAGE` (0:0 for an error without a location),
// and any further `# note: TEXT` lines give text that must appear in one of its notes. Formats
// whose comments start otherwise (POV-Ray's `//`) write that in place of `#`.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "glint/scene/scene_error.h"

namespace glint::testing {

struct ExpectedError {
    int line = -1;
    int column = -1;
    std::string message;
    std::vector<std::string> notes;
};

// Nothing when the header is malformed; the test then fails for that file.
inline std::optional<ExpectedError> read_expected_error(const std::filesystem::path& file,
                                                        const std::string& comment = "#") {
    std::ifstream in(file, std::ios::binary);
    std::string line;
    ExpectedError e;
    const std::string prefix = comment + " error: ";
    const std::string note = comment + " note: ";
    if (!std::getline(in, line) || !line.starts_with(prefix)) return std::nullopt;
    std::istringstream header(line.substr(prefix.size()));
    char colon1 = 0, colon2 = 0;
    if (!(header >> e.line >> colon1 >> e.column >> colon2) || colon1 != ':' || colon2 != ':') {
        return std::nullopt;
    }
    std::getline(header >> std::ws, e.message);
    while (std::getline(in, line) && line.starts_with(note))
        e.notes.push_back(line.substr(note.size()));
    return e;
}

// The files of a folder with the extension, in name order.
inline std::vector<std::filesystem::path> files_with_extension(const std::filesystem::path& dir,
                                                               const std::string& extension) {
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        if (entry.path().extension() == extension) files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end());
    return files;
}

// Runs load (which reads `file`) and checks that it throws the SceneError the file states:
// location, message, notes, and a quoted source line when located.
inline void expect_stated_error(const std::filesystem::path& file,
                                const std::function<void()>& load,
                                const std::string& comment = "#") {
    SCOPED_TRACE(file.filename().string());
    const auto expected = read_expected_error(file, comment);
    ASSERT_TRUE(expected) << "first line must be '" << comment << " error: LINE:COL: MESSAGE'";
    try {
        load();
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

}  // namespace glint::testing
