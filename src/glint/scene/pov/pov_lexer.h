// The tokens of POV-Ray's scene description language: numbers, strings, identifiers (keywords
// are identifiers, told apart by the parser), symbols and directives (`#declare`), past
// whitespace, `//` comments and `/* */` comments (which nest, as in POV-Ray). A file is read into
// tokens at once, so that `#while` loops and macros can go back to a token's index.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "glint/scene/pov/pov_files.h"

namespace glint {

enum class PovTokenKind : std::uint8_t {
    identifier,  // text: the name
    number,      // number: the value; text: as written
    string,      // text: the value, escapes resolved
    symbol,      // text: one of { } ( ) [ ] < > , ; + - * / = ! ? : . & | ^ <= >= !=
    directive,   // text: the word after `#` ("declare")
    end,         // the end of the file
};

struct PovToken {
    PovTokenKind kind = PovTokenKind::end;
    std::string text;
    double number = 0;
    PovPosition at;

    bool is(PovTokenKind k, std::string_view t) const { return kind == k && text == t; }
    bool is_symbol(std::string_view t) const { return is(PovTokenKind::symbol, t); }
    bool is_word(std::string_view t) const { return is(PovTokenKind::identifier, t); }
};

// The tokens of file `file` of `files`, ending with one `end` token. Throws SceneError for an
// unterminated string or comment, an unknown character or escape, or a malformed number.
std::vector<PovToken> lex_pov(const PovFiles& files, std::uint32_t file);

// How messages show a token: `"sphere"`, `the number 1.5`, `the end of the file`.
std::string describe(const PovToken& token);

}  // namespace glint
