// The files of a POV-Ray scene (the scene and what it includes), their text, and errors located
// in them: file:line:col, the line with a caret under the token, and the include stack as notes.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "glint/scene/scene_error.h"

namespace glint {

// Where a token is: a file of PovFiles, 1-based line and column (bytes), and its length.
struct PovPosition {
    std::uint32_t file = 0;
    std::uint32_t line = 0;
    std::uint32_t column = 0;
    std::uint32_t length = 1;
};

class PovFiles {
public:
    // The file's index. `name` is how messages name it (as the scene or #include wrote it);
    // `included_at` is the #include's position (for the notes), none for the scene itself.
    std::uint32_t add(std::string name, std::string text, const PovPosition* included_at = nullptr);

    const std::string& name(std::uint32_t file) const { return files_[file].name; }
    std::string_view text(std::uint32_t file) const { return files_[file].text; }
    std::size_t size() const { return files_.size(); }

    // An error at `where`, quoting its line, with "included from" notes after `notes`.
    SceneError error_at(const PovPosition& where, std::string message,
                        std::vector<std::string> notes = {}) const;

private:
    struct File {
        std::string name;
        std::string text;
        bool included = false;
        PovPosition included_at;
    };
    std::vector<File> files_;
};

}  // namespace glint
