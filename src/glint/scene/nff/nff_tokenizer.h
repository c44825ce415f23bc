// NFF text as a stream of whitespace-separated tokens with their line and column, numbers read
// with std::from_chars, and SceneErrors that quote the line and underline the token.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "glint/scene/nff/nff_scene.h"
#include "glint/scene/quote.h"
#include "glint/scene/scene_error.h"

namespace glint {

struct NffToken {
    std::string_view text;     // empty at the end of the text
    std::uint32_t line = 0;    // 1-based
    std::uint32_t column = 0;  // 1-based, in bytes

    bool at_end() const { return text.empty(); }
    NffLocation location() const { return {line, column}; }
};

// The entity being read ("sphere" and its keyword token) and one of its values ("radius", or
// "x" of vertex 3), to say in errors what was expected where.
struct NffEntity {
    std::string_view name;
    NffToken keyword;
};
struct NffField {
    const char* name;
    std::uint32_t vertex = 0;  // 1-based; 0 when the value is not a vertex's
};

// "the sphere's radius", "the polygon's vertex 3 x".
std::string describe(const NffEntity& entity, const NffField& field);

class NffTokenizer {
public:
    // text must outlive the tokenizer.
    NffTokenizer(std::string_view text, std::string file_name);

    const std::string& file_name() const { return file_name_; }

    // The next token, past whitespace and `#` comments (which run to the end of the line).
    NffToken next();
    // The token next() would return, without consuming it.
    NffToken peek();
    // Bytes from the current position to the end: a bound on what the rest of the file can hold.
    std::size_t remaining_bytes() const { return text_.size() - pos_; }

    // The next token, which must exist: the end of the file inside an entity is an error.
    NffToken require(const NffEntity& entity, const NffField& field);
    // The next token as a finite float.
    float number(const NffEntity& entity, const NffField& field) {
        return number_of(require(entity, field), entity, field);
    }
    // A token already read as a finite float.
    float number_of(const NffToken& token, const NffEntity& entity, const NffField& field) const;
    // A token already read as a whole number; out-of-range values saturate to the int64 limits.
    std::int64_t integer_of(const NffToken& token, const NffEntity& entity,
                            const NffField& field) const;

    // An error at a token, quoting its line with the caret under the token.
    SceneError error_at(const NffToken& token, std::string message,
                        std::vector<std::string> notes = {}) const;
    // An error just past the last token read, for a file that ends too early.
    SceneError error_at_end(std::string message, std::vector<std::string> notes = {}) const;

private:
    void skip_space();

    std::string_view text_;
    std::string file_name_;
    std::size_t pos_ = 0;
    std::uint32_t line_ = 1;
    std::size_t line_start_ = 0;
    NffToken last_;  // the last token read
};

}  // namespace glint
