// The scan of glTF JSON for values Assimp mishandles.
#include "glint/scene/mesh/gltf_validator.h"

#include <algorithm>
#include <charconv>
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

// The index just past the JSON value that starts at `p` (a string, an object, an array or a
// bare number or word), found by counting brackets outside strings: no recursion, so no depth
// of nesting can exhaust the stack. npos when the text ends first.
std::size_t value_end(std::string_view text, std::size_t p) {
    int depth = 0;
    for (; p < text.size(); ++p) {
        const char c = text[p];
        if (c == '"') {
            p = string_end(text, p + 1);
            if (p == std::string_view::npos) return p;
            if (depth == 0) return p + 1;
        } else if (c == '{' || c == '[') {
            ++depth;
        } else if (c == '}' || c == ']') {
            if (--depth <= 0) return depth == 0 ? p + 1 : p;
        } else if (depth == 0 && (c == ',' || c == ' ' || c == '\t' || c == '\n' || c == '\r')) {
            return p;
        }
    }
    return depth == 0 ? p : std::string_view::npos;
}

// The start of the value of `key` among the members of the object whose '{' is at `p`, or
// npos (no such member, or not an object).
std::size_t member(std::string_view text, std::size_t p, std::string_view key) {
    if (p >= text.size() || text[p] != '{') return std::string_view::npos;
    p = skip_space(text, p + 1);
    while (p < text.size() && text[p] == '"') {
        const std::size_t key_end = string_end(text, p + 1);
        if (key_end == std::string_view::npos) return key_end;
        const std::string_view name = text.substr(p + 1, key_end - p - 1);
        p = skip_space(text, key_end + 1);
        if (p >= text.size() || text[p] != ':') return std::string_view::npos;
        p = skip_space(text, p + 1);
        if (name == key) return p;
        p = value_end(text, p);
        if (p == std::string_view::npos) return p;
        p = skip_space(text, p);
        if (p >= text.size() || text[p] != ',') return std::string_view::npos;
        p = skip_space(text, p + 1);
    }
    return std::string_view::npos;
}

// The start of element `index` of the array whose '[' is at `p`, or npos.
std::size_t element(std::string_view text, std::size_t p, std::size_t index) {
    if (p >= text.size() || text[p] != '[') return std::string_view::npos;
    p = skip_space(text, p + 1);
    for (std::size_t i = 0; i < index; ++i) {
        p = value_end(text, p);
        if (p == std::string_view::npos) return p;
        p = skip_space(text, p);
        if (p >= text.size() || text[p] != ',') return std::string_view::npos;
        p = skip_space(text, p + 1);
    }
    return p < text.size() && text[p] != ']' ? p : std::string_view::npos;
}

// The bare token (a number, true, ...) or the string's text of the value at `p`.
std::string_view value_text(std::string_view text, std::size_t p) {
    const std::size_t end = value_end(text, p);
    if (end == std::string_view::npos) return {};
    if (text[p] == '"') return text.substr(p + 1, end - p - 2);
    return text.substr(p, end - p);
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
    // The JSON text: a .glb file's first chunk (validate_glb has checked its length), and where
    // it starts in the file.
    std::size_t offset = 0;
    std::string_view json = bytes;
    if (binary && bytes.size() >= 20) {
        const auto byte = [&](std::size_t i) { return std::uint32_t(std::uint8_t(bytes[i])); };
        const std::uint32_t length = byte(12) | byte(13) << 8 | byte(14) << 16 | byte(15) << 24;
        offset = 20;
        json = bytes.substr(20, std::min<std::size_t>(length, bytes.size() - 20));
    }
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
    // Assimp leaks what it has built when it throws on indices that are not unsigned integers.
    const std::size_t root = json.find('{');
    const std::size_t accessors = member(json, root, "accessors");
    for (std::size_t at = json.find("\"indices\""); at != std::string_view::npos;
         at = json.find("\"indices\"", at + 1)) {
        constexpr std::size_t kKeyLength = 9;
        const std::size_t colon = skip_space(json, at + kKeyLength);
        if (colon >= json.size() || json[colon] != ':') continue;
        const std::size_t p = skip_space(json, colon + 1);
        if (p >= json.size()) continue;
        std::size_t index = 0;
        const std::string_view digits = value_text(json, p);
        if (digits.empty() ||
            std::from_chars(digits.data(), digits.data() + digits.size(), index).ptr !=
                digits.data() + digits.size())
            continue;  // a sparse accessor's indices (an object), or not JSON Assimp reads
        const std::size_t accessor = element(json, accessors, index);
        if (accessor == std::string_view::npos) continue;  // Assimp names the missing accessor
        const std::size_t type_at = member(json, accessor, "type"),
                          component_at = member(json, accessor, "componentType");
        const std::string_view type = type_at == std::string_view::npos ? ""
                                                                        : value_text(json, type_at),
                               component = component_at == std::string_view::npos
                                               ? ""
                                               : value_text(json, component_at);
        if (type == "SCALAR" && (component == "5121" || component == "5123" || component == "5125"))
            continue;
        fail(offset + p, digits.size(),
             "a mesh primitive's indices are accessor " + std::string(digits) + ", of type \"" +
                 std::string(type) + "\" and componentType " +
                 (component.empty() ? "(none)" : std::string(component)) +
                 "; glTF indices are SCALAR unsigned integers (componentType 5121, 5123 or 5125)");
    }
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
