// Typed reading of single YAML values (numbers, integers, booleans, points, colours, sequences)
// for the scene loader. Every failure is a SceneError at the offending node. Internal to
// glint_scene: yaml-cpp stays private.
#pragma once

#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "glint/math/color.h"
#include "glint/math/vector.h"
#include "glint/scene/quote.h"
#include "glint/scene/scene_error.h"
#include "glint/scene/schema/value_range.h"
#include "glint/scene/yaml/yaml_source.h"

namespace glint {

// How messages name a value: `what` is the thing it belongs to ("sphere", may be empty) and
// `key` its key ("radius", or "vertices[1]" for a list element). An empty value is reported at
// key_node, since yaml-cpp places empty values at the next token.
struct Field {
    Field(std::string what_, std::string key_, YAML::Node key_node_ = {})
        : what(std::move(what_)), key(std::move(key_)), key_node(std::move(key_node_)) {}

    std::string what;
    std::string key;
    YAML::Node key_node;  // default: none
};

struct IntRange {
    std::int64_t min;
    std::int64_t max;
};

// "a sequence", "a map", "nothing", a number as written, or a string in quotes.
std::string describe(const YAML::Node& node);
// A number as a message shows it, in the shortest form that reads back the same.
std::string format_number(double value);
std::string format_number(float value);
// "a, b, c"
std::string join(std::span<const std::string_view> names);

// `expected <expected> for "<key>", got <what the node is>`, at the node, or at its key when the
// value is empty. A quoted number gets a note that quotes make strings.
SceneError type_error(const YamlSource& source, const YAML::Node& node, const Field& field,
                      std::string_view expected);

// Readers of single values; `field` names the value in messages.
float read_number(const YamlSource& source, const YAML::Node& node, const Field& field,
                  Range range = kAnyNumber);
std::int64_t read_integer(const YamlSource& source, const YAML::Node& node, const Field& field,
                          IntRange range);
bool read_bool(const YamlSource& source, const YAML::Node& node, const Field& field);
std::string read_string(const YamlSource& source, const YAML::Node& node, const Field& field);
Point3 read_point(const YamlSource& source, const YAML::Node& node, const Field& field);
Vector3 read_vector(const YamlSource& source, const YAML::Node& node, const Field& field);
Point2 read_point2(const YamlSource& source, const YAML::Node& node, const Field& field);
// [r, g, b] or one number for a gray; every channel finite and >= 0.
Color read_color(const YamlSource& source, const YAML::Node& node, const Field& field);
// The items of a sequence, checked to number `count` when count > 0. `expected` describes the
// sequence for messages ("a point [x, y, z]").
std::vector<YAML::Node> read_sequence(const YamlSource& source, const YAML::Node& node,
                                      const Field& field, std::string_view expected,
                                      std::size_t count = 0);

// Error for a name that is not one of `names` (sorted): `unknown <kind> "x"` with a note listing
// them as `<plural> are: ...` and a suggestion.
SceneError unknown_name(const YamlSource& source, const YAML::Node& at, std::string_view kind,
                        std::string_view plural, std::string_view name,
                        std::span<const std::string_view> names);

// v scaled to unit length, computed in double so that tiny and huge float vectors survive;
// nothing for the zero vector.
std::optional<Vector3> unit_vector(Vector3 v);
// "[x, y, z]"
std::string format_vector(Vector3 v);

}  // namespace glint
