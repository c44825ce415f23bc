// The error every scene loader throws: where (file:line:col), what, and notes that help fix it.
#pragma once

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace glint {

struct SourceLocation {
    std::string file;
    int line = 0;    // 1-based; 0 when unknown
    int column = 0;  // 1-based; 0 when unknown
};

class SceneError : public std::runtime_error {
public:
    SceneError(SourceLocation location, std::string message, std::vector<std::string> notes = {},
               std::string source_line = {}, int span = 1)
        : std::runtime_error(message),
          location_(std::move(location)),
          message_(std::move(message)),
          notes_(std::move(notes)),
          source_line_(std::move(source_line)),
          span_(span) {}

    const SourceLocation& location() const { return location_; }
    const std::string& message() const { return message_; }
    const std::vector<std::string>& notes() const { return notes_; }
    // The text of the offending line, without its newline; empty when not known.
    const std::string& source_line() const { return source_line_; }
    // How many characters the caret marks, from the column on.
    int span() const { return span_; }

private:
    SourceLocation location_;
    std::string message_;
    std::vector<std::string> notes_;
    std::string source_line_;
    int span_;
};

// Formats the error as a compiler does:
//   scene.yaml:14:11: error: unknown object type "spere"
//      14 |   - type: spere
//         |           ^~~~~
//   note: object types are: box, plane, sphere, triangle (did you mean "sphere"?)
std::string format_scene_error(const SceneError& error);

}  // namespace glint
