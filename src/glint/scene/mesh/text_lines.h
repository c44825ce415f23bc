// Line-by-line reading of text mesh files (OBJ, MTL, ASCII PLY) for the validators, which report
// errors at file:line:col with the line quoted. Internal to the mesh importer.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "glint/scene/scene_error.h"

namespace glint {

// A whitespace-separated token and its 1-based column.
struct Token {
    std::string_view text;
    int column = 0;
};

// Splits a line at spaces and tabs; a '#' starts a comment that runs to the end of the line.
std::vector<Token> split_tokens(std::string_view line, bool hash_comments = true);

// Which characters end a line: "\n" (and "\r\n"); or, as Assimp's OBJ and MTL readers do, any
// of "\n", "\r", "\f" and NUL ("\r\n" one break), which a validator must follow to see the lines
// Assimp will read.
enum class LineBreaks { newline, obj };

// The text's lines, without their line breaks (a lone "\r" at a line's end is dropped too).
class TextLines {
public:
    TextLines(std::string_view text, std::string file_name,
              LineBreaks breaks = LineBreaks::newline);

    std::size_t size() const { return starts_.size(); }
    std::string_view line(std::size_t index) const;  // 0-based
    const std::string& file_name() const { return file_name_; }

    // An error at 1-based line and column, quoting the line, with the caret under `span`
    // characters.
    SceneError error_at(std::size_t line_number, int column, int span, std::string message,
                        std::vector<std::string> notes = {}) const;

private:
    std::string_view text_;
    std::string file_name_;
    std::vector<std::size_t> starts_, ends_;  // each line's first character and its end
};

// A float parsed from the whole token, or nothing when it is not a number. "nan", "inf" and
// numbers that overflow come back as such; callers decide whether they are allowed.
std::optional<float> parse_float(std::string_view token);
// A decimal integer from the whole token (an optional sign, then digits), or nothing.
std::optional<long long> parse_integer(std::string_view token);

// Reads a whole file of at most max_bytes; throws SceneError naming it otherwise.
std::string read_text_file(const std::string& file, std::uintmax_t max_bytes);

}  // namespace glint
