// Maps with a fixed set of keys, read key by key: unknown keys, duplicates and missing keys are
// errors with the list of accepted keys and a "did you mean". Internal to glint_scene.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "glint/scene/schema/entity_schema.h"
#include "glint/scene/yaml/yaml_reader.h"

namespace glint {

struct MapEntry {
    std::string key;
    YAML::Node key_node;
    YAML::Node value;
};

// The entries of a map in file order. An error unless node is a map whose keys are distinct
// scalars.
std::vector<MapEntry> read_map(const YamlSource& source, const YAML::Node& node,
                               const Field& field);
const MapEntry* find_entry(std::span<const MapEntry> entries, std::string_view key);

// The "type" of a map that describes one of several kinds of thing (objects, lights, textures):
// one of `types` (sorted). `kind` names the family in messages: for "object" they read
// `object is missing required key "type"` and `unknown object type "spere"`. With a fallback
// the key is optional.
std::string read_type(const YamlSource& source, const YAML::Node& node,
                      std::span<const MapEntry> entries, std::string_view kind,
                      std::span<const std::string_view> types,
                      std::optional<std::string_view> fallback = {});

// Whether the "accepts:" note of an unknown key lists "type". A required type chose the kind
// of map, so the user already knows it; an optional one (the camera's, perspective by default)
// may be news, so it is listed like any other key.
enum class TypeKey { implied, listed };

// A map with a fixed set of keys, read key by key. The constructor rejects unknown keys up front,
// so a misspelt key is reported as such rather than as a missing one.
class MapReader {
public:
    // `what` names the map in messages ("sphere"); `keys` are the keys it accepts.
    MapReader(const YamlSource& source, const YAML::Node& node, std::vector<MapEntry> entries,
              std::string what, std::vector<std::string_view> keys,
              TypeKey type_key = TypeKey::implied);
    // Reads the entries of node itself.
    MapReader(const YamlSource& source, const YAML::Node& node, const Field& field,
              std::string what, std::vector<std::string_view> keys,
              TypeKey type_key = TypeKey::implied);
    // Accepts the schema's keys and `more`; number(key) then reads by the schema.
    MapReader(const YamlSource& source, const YAML::Node& node, std::vector<MapEntry> entries,
              std::string what, const EntitySchema& schema,
              std::vector<std::string_view> more = {});
    MapReader(const YamlSource& source, const YAML::Node& node, const Field& field,
              std::string what, const EntitySchema& schema,
              std::vector<std::string_view> more = {});

    const YamlSource& source() const { return source_; }
    const YAML::Node& node() const { return node_; }
    const std::string& what() const { return what_; }
    Field field(std::string_view key) const;

    const MapEntry* find(std::string_view key) const;
    bool has(std::string_view key) const { return find(key) != nullptr; }
    // The entry of a required key; an error at the map when it is missing.
    const MapEntry& require(std::string_view key) const;

    // Typed values. Without a fallback the key is required.
    float number(std::string_view key, Range range, std::optional<float> fallback = {}) const;
    // By the schema: its range, and its default when that is a plain number (else required).
    float number(std::string_view key) const;
    // By the schema's range, with a default it cannot write as a number ("1e-3 × scale").
    float number_or(std::string_view key, float fallback) const;
    int integer(std::string_view key, IntRange range, std::optional<int> fallback = {}) const;
    // By the schema, as number(key) and number_or are.
    int integer(std::string_view key) const;
    int integer_or(std::string_view key, int fallback) const;
    bool boolean(std::string_view key, bool fallback) const;
    Point3 point(std::string_view key, std::optional<Point3> fallback = {}) const;
    Vector3 vector(std::string_view key, std::optional<Vector3> fallback = {}) const;
    // A vector scaled to unit length; an error when it is zero.
    Vector3 direction(std::string_view key, std::optional<Vector3> fallback = {}) const;
    Color color(std::string_view key, std::optional<Color> fallback = {}) const;
    // One of `names` (sorted), reported as `unknown <kind>` otherwise.
    std::string choice(std::string_view key, std::span<const std::string_view> names,
                       std::string_view kind, std::string_view plural,
                       std::string_view fallback) const;

private:
    const YamlSource& source_;
    YAML::Node node_;
    std::vector<MapEntry> entries_;
    std::string what_;
    std::vector<std::string_view> keys_;
    const EntitySchema* schema_ = nullptr;
};

}  // namespace glint
