// The ASCII STL grammar as a state machine over the lines; see stl_validator.h.
#include "glint/scene/mesh/stl_validator.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "glint/scene/mesh/text_lines.h"

namespace glint {

namespace {

// Assimp's test (STLLoader.cpp): a binary STL is exactly as long as its triangle count says.
bool is_binary_stl(std::string_view bytes) {
    if (bytes.size() < 84) return false;
    std::uint32_t count = 0;
    std::memcpy(&count, bytes.data() + 80, 4);  // little-endian, as STL is; so is every target
    return 84 + 50 * std::uint64_t(count) == bytes.size();
}

bool starts_with_solid(std::string_view bytes) {
    const std::size_t first = bytes.find_first_not_of(" \t\r\n");
    return first != std::string_view::npos && bytes.substr(first, 5) == "solid";
}

// Built by appending: GCC 12's -Wrestrict misfires on "\"" + std::string (GCC bug 105651).
std::string in_quotes(std::string_view s) {
    std::string out;
    out.reserve(s.size() + 2);
    out += '"';
    out += s;
    out += '"';
    return out;
}

class StlValidator {
public:
    StlValidator(const std::filesystem::path& file, std::string_view text)
        : lines_(text, file.string()) {}

    void run() {
        for (std::size_t i = 0; i < lines_.size(); ++i) {
            line_ = i + 1;
            tokens_ = split_tokens(lines_.line(i), false);
            if (tokens_.empty()) continue;
            step();
        }
        if (state_ != State::outside && state_ != State::in_solid) {
            throw lines_.error_at(facet_.line, facet_.column, 5,
                                  "the file ends inside this facet (is it truncated?)");
        }
    }

private:
    enum class State { outside, in_solid, in_facet, in_loop, after_loop };

    void step() {
        const std::string_view key = tokens_[0].text;
        switch (state_) {
            case State::outside:
                // As Assimp, which takes "solid" followed by anything for the start of a solid.
                if (!key.starts_with("solid")) unexpected("\"solid\"");
                // The rest of the line is the solid's name, to glint; Assimp's name ends at the
                // first space, and it starts a facet at a word "facet" after it.
                for (std::size_t k = 1; k < tokens_.size(); ++k) {
                    if (tokens_[k].text == "facet") {
                        throw error_at(tokens_[k], "a facet on the line of \"solid\"",
                                       {"a solid's name cannot hold the word \"facet\": start the "
                                        "facet on a line of its own"});
                    }
                }
                state_ = State::in_solid;
                return;
            case State::in_solid:
                if (key == "endsolid") {
                    state_ = State::outside;
                } else if (key == "facet") {
                    if (tokens_.size() < 2 || tokens_[1].text != "normal") {
                        expected_after(0, "\"normal\"");
                    }
                    numbers(2, "facet normal");
                    facet_ = {line_, tokens_[0].column};
                    state_ = State::in_facet;
                } else {
                    unexpected("\"facet\" or \"endsolid\"");
                }
                return;
            case State::in_facet:
                if (key != "outer") unexpected("\"outer loop\"");
                if (tokens_.size() < 2 || tokens_[1].text != "loop") expected_after(0, "\"loop\"");
                nothing_after(2);
                vertices_ = 0;
                state_ = State::in_loop;
                return;
            case State::in_loop:
                if (key == "vertex") {
                    if (++vertices_ > 3) {
                        throw error_at(tokens_[0], "a facet with more than 3 vertices",
                                       {"STL facets are triangles"});
                    }
                    numbers(1, "vertex");
                } else if (key == "endloop") {
                    if (vertices_ < 3) {
                        throw error_at(tokens_[0], "the facet has " + std::to_string(vertices_) +
                                                       " vertices; STL facets are triangles");
                    }
                    nothing_after(1);
                    state_ = State::after_loop;
                } else {
                    unexpected("\"vertex\" or \"endloop\"");
                }
                return;
            case State::after_loop:
                if (key != "endfacet") unexpected("\"endfacet\"");
                nothing_after(1);
                state_ = State::in_solid;
                return;
        }
    }

    SceneError error_at(const Token& t, std::string message,
                        std::vector<std::string> notes = {}) const {
        return lines_.error_at(line_, t.column, int(t.text.size()), std::move(message),
                               std::move(notes));
    }

    [[noreturn]] void unexpected(const char* what) const {
        const std::string_view got = tokens_[0].text;
        std::vector<std::string> notes;
        for (const char c : got) {
            if (static_cast<unsigned char>(c) < 32 || static_cast<unsigned char>(c) > 126) {
                notes.push_back(
                    "this looks like binary data: a binary STL file is 84 + 50 n bytes long for "
                    "the n triangles its header counts, and this file's length does not match");
                break;
            }
        }
        throw error_at(tokens_[0], std::string("expected ") + what + ", got " + in_quotes(got),
                       std::move(notes));
    }

    [[noreturn]] void expected_after(std::size_t k, const char* what) const {
        if (k + 1 < tokens_.size()) {
            throw error_at(tokens_[k + 1], std::string("expected ") + what + ", got " +
                                               in_quotes(tokens_[k + 1].text));
        }
        throw error_at(tokens_[k],
                       std::string("expected ") + what + " after " + in_quotes(tokens_[k].text));
    }

    void nothing_after(std::size_t count) const {
        if (tokens_.size() > count) {
            throw error_at(tokens_[count], "unexpected " + in_quotes(tokens_[count].text) +
                                               " after " + in_quotes(tokens_[count - 1].text));
        }
    }

    // Exactly three finite numbers from token `first` on.
    void numbers(std::size_t first, const char* what) const {
        if (tokens_.size() < first + 3) {
            const Token& last = tokens_.back();
            throw error_at(last, std::string(what) + " needs 3 numbers, got " +
                                     std::to_string(tokens_.size() - first));
        }
        for (std::size_t k = first; k < first + 3; ++k) {
            const Token& t = tokens_[k];
            const auto value = parse_float(t.text);
            if (!value) throw error_at(t, "expected a number, got " + in_quotes(t.text));
            if (!std::isfinite(*value)) {
                throw error_at(t, std::string(what) +
                                      " has a coordinate that is not finite: " + in_quotes(t.text));
            }
        }
        nothing_after(first + 3);
    }

    TextLines lines_;
    State state_ = State::outside;
    std::size_t line_ = 0;  // 1-based, of the tokens being checked
    struct {
        std::size_t line = 0;
        int column = 0;
    } facet_;           // where the open facet starts
    int vertices_ = 0;  // in the open loop
    std::vector<Token> tokens_;
};

}  // namespace

void validate_stl(const std::filesystem::path& file, std::string_view bytes) {
    if (is_binary_stl(bytes) || !starts_with_solid(bytes)) return;
    StlValidator(file, bytes).run();
}

}  // namespace glint
