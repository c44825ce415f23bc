// The scan of glTF JSON for values Assimp mishandles.
#include "glint/scene/mesh/gltf_validator.h"

#include <algorithm>
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

}  // namespace

void validate_gltf_json(const std::filesystem::path& file, std::string_view bytes, bool binary) {
    constexpr std::string_view kKey = "\"mimeType\"";
    for (std::size_t at = bytes.find(kKey); at != std::string_view::npos;
         at = bytes.find(kKey, at + kKey.size())) {
        std::size_t p = skip_space(bytes, at + kKey.size());
        if (p >= bytes.size() || bytes[p] != ':') continue;
        p = skip_space(bytes, p + 1);
        if (p >= bytes.size() || bytes[p] != '"') continue;
        const std::size_t end = string_end(bytes, p + 1);
        if (end == std::string_view::npos) continue;  // Assimp's parser refuses the file
        const std::string_view value = bytes.substr(p + 1, end - p - 1);
        if (value.find('/') != std::string_view::npos) continue;
        const std::string message = "image mimeType \"" + std::string(value) +
                                    "\" is not a media type (such as \"image/png\")";
        if (binary) throw SceneError({file.string(), 0, 0}, message);
        const TextLines lines(bytes, file.string());
        const std::size_t line_start = bytes.rfind('\n', p) + 1;  // npos + 1 is 0
        const auto line =
            std::size_t(std::count(bytes.begin(), bytes.begin() + std::ptrdiff_t(p), '\n'));
        throw lines.error_at(line + 1, int(p - line_start) + 1, int(value.size()) + 2, message);
    }
}

}  // namespace glint
