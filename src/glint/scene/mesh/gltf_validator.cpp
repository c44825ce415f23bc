// The scan of glTF JSON for values Assimp mishandles.
#include "glint/scene/mesh/gltf_validator.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <string>

#include "glint/scene/mesh/text_lines.h"
#include "glint/scene/scene_error.h"

namespace glint {

namespace {

std::size_t skip_space(std::string_view text, std::size_t p) {
    while (p < text.size() &&
           (text[p] == ' ' || text[p] == '\t' || text[p] == '\n' || text[p] == '\r')) {
        ++p;
    }
    return p;
}

// The end of the JSON string whose text starts at `p` (after its opening quote): the index of
// its closing quote, or npos.
std::size_t string_end(std::string_view text, std::size_t p) {
    for (; p < text.size(); ++p) {
        if (text[p] == '\\') {
            ++p;
        } else if (text[p] == '"') {
            return p;
        }
    }
    return std::string_view::npos;
}

// Calls check(value, at) for every string value of `key` ("\"mimeType\""), at the index of its
// opening quote.
template <class Check>
void for_each_string_value(std::string_view text, std::string_view key, const Check& check) {
    for (std::size_t at = text.find(key); at != std::string_view::npos;
         at = text.find(key, at + key.size())) {
        std::size_t p = skip_space(text, at + key.size());
        if (p >= text.size() || text[p] != ':') continue;
        p = skip_space(text, p + 1);
        if (p >= text.size() || text[p] != '"') continue;
        const std::size_t end = string_end(text, p + 1);
        if (end == std::string_view::npos) continue;  // Assimp's parser refuses the file
        check(text.substr(p + 1, end - p - 1), p);
    }
}

bool is_base64(char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '+' ||
           c == '/' || c == '=';
}

// The index in `uri` of the first character of its base64 data that is not base64 (a JSON
// "\/" counts as '/'), or npos; npos too for a URI that is not base64 data.
std::size_t first_non_base64(std::string_view uri) {
    const std::size_t comma = uri.find(',');
    if (uri.substr(0, 5) != "data:" || comma == std::string_view::npos)
        return std::string_view::npos;
    const std::string_view header = uri.substr(0, comma);
    if (header.size() < 7 || header.substr(header.size() - 7) != ";base64")
        return std::string_view::npos;
    for (std::size_t i = comma + 1; i < uri.size(); ++i) {
        if (uri[i] == '\\' && i + 1 < uri.size() && uri[i + 1] == '/') {
            ++i;
        } else if (!is_base64(uri[i])) {
            return i;
        }
    }
    return std::string_view::npos;
}

}  // namespace

void validate_gltf_json(const std::filesystem::path& file, std::string_view bytes, bool binary) {
    // The error at `p` (a .gltf file's line and column), underlining `length` characters.
    const auto fail = [&](std::size_t p, std::size_t length, const std::string& message) {
        if (binary) throw SceneError({file.string(), 0, 0}, message);
        const TextLines lines(bytes, file.string());
        const std::size_t line_start = bytes.rfind('\n', p) + 1;  // npos + 1 is 0
        const auto line =
            std::size_t(std::count(bytes.begin(), bytes.begin() + std::ptrdiff_t(p), '\n'));
        throw lines.error_at(line + 1, int(p - line_start) + 1, int(length), message);
    };
    for_each_string_value(bytes, "\"mimeType\"", [&](std::string_view value, std::size_t at) {
        if (value.find('/') != std::string_view::npos) return;
        fail(at, value.size() + 2,
             "image mimeType \"" + std::string(value) +
                 "\" is not a media type (such as \"image/png\")");
    });
    // Assimp allocates a data URI's bytes, then throws at a character of 128 or more and
    // loses them.
    for_each_string_value(bytes, "\"uri\"", [&](std::string_view value, std::size_t at) {
        const std::size_t bad = first_non_base64(value);
        if (bad == std::string_view::npos) return;
        char code[8];
        std::snprintf(code, sizeof code, "0x%02x", unsigned(std::uint8_t(value[bad])));
        const bool printable = value[bad] >= ' ' && value[bad] <= '~';
        fail(at + 1 + bad, 1,
             "a base64 data URI holds " +
                 (printable ? "'" + std::string(1, value[bad]) + "'"
                            : "the byte " + std::string(code)) +
                 " at its character " + std::to_string(bad + 1) +
                 ", which is not base64 (A-Z, a-z, 0-9, +, / and =)");
    });
}

}  // namespace glint
