// The YAML text being parsed, for errors that quote the offending line and underline its token.
// Internal to glint_scene: yaml-cpp stays private.
#pragma once

#include <yaml-cpp/yaml.h>

#include <string>
#include <string_view>
#include <vector>

#include "glint/scene/scene.h"
#include "glint/scene/scene_error.h"

namespace glint {

// The 1-based place of a yaml-cpp mark (0-based); {0, 0} for a null mark.
inline TextPosition text_position(const YAML::Mark& mark) {
    if (mark.is_null() || mark.line < 0 || mark.column < 0) return {};
    return {mark.line + 1, mark.column + 1};
}

// Makes SceneErrors located in the text.
class YamlSource {
public:
    // text must outlive the source.
    YamlSource(std::string_view text, std::string file_name);

    const std::string& file_name() const { return file_name_; }
    // An error without a position in the file.
    SceneError error(std::string message, std::vector<std::string> notes = {}) const;
    // An error at a yaml-cpp mark (0-based); span is the caret's width.
    SceneError error_at(const YAML::Mark& mark, int span, std::string message,
                        std::vector<std::string> notes = {}) const;
    // An error at a node, with the caret under its whole token when it fits on one line.
    SceneError error_at(const YAML::Node& node, std::string message,
                        std::vector<std::string> notes = {}) const;

    // A warning about what loads but does nothing, as a scene's warnings hold it:
    // "scene.yaml:12:5: message".
    std::string warning_at(const YAML::Node& node, const std::string& message) const;

    // A line of the text, 0-based, without its line break; empty when out of range.
    std::string_view line(int index) const;
    int line_count() const { return int(line_starts_.size()); }

private:
    int span_of(const YAML::Node& node) const;

    std::string_view text_;
    std::string file_name_;
    std::vector<std::size_t> line_starts_;
};

// Inside a catch block: throws the exception in flight again as a SceneError located in the
// text (yaml-cpp's parse errors at their marks; a SceneError as it is). `what` names what was
// being read in messages without a place: "out of memory while reading the scene".
[[noreturn]] void rethrow_as_scene_error(const YamlSource& source, const std::string& what);

}  // namespace glint
