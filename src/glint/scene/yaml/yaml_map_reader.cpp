// Reading maps: entries in file order, duplicate and unknown keys, the "type" of a family
// member, and MapReader's typed accessors.
#include "glint/scene/yaml/yaml_map_reader.h"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <unordered_map>

#include "glint/scene/suggest.h"

namespace glint {

std::vector<MapEntry> read_map(const YamlSource& source, const YAML::Node& node,
                               const Field& field) {
    if (!node.IsMap()) throw type_error(source, node, field, "a map");
    std::vector<MapEntry> entries;
    // Key -> index into entries. A hash keeps large maps (materials) linear, not quadratic.
    std::unordered_map<std::string, std::size_t> seen;
    for (auto it = node.begin(); it != node.end(); ++it) {
        const YAML::Node key = it->first;
        if (!key.IsScalar()) {
            throw source.error_at(
                key, "expected a key name in " + quote(field.key) + ", got " + describe(key));
        }
        // yaml-cpp keeps both entries of a repeated key; a scene must say things once.
        if (const auto first = seen.find(key.Scalar()); first != seen.end()) {
            const YAML::Mark m = entries[first->second].key_node.Mark();
            throw source.error_at(
                key, "duplicate key " + quote(key.Scalar()),
                {quote(key.Scalar()) + " was first given at line " + std::to_string(m.line + 1) +
                 ", column " + std::to_string(m.column + 1)});
        }
        seen.emplace(key.Scalar(), entries.size());
        entries.push_back({key.Scalar(), key, it->second});
    }
    return entries;
}

const MapEntry* find_entry(std::span<const MapEntry> entries, std::string_view key) {
    for (const MapEntry& entry : entries) {
        if (entry.key == key) return &entry;
    }
    return nullptr;
}

std::string read_type(const YamlSource& source, const YAML::Node& node,
                      std::span<const MapEntry> entries, std::string_view kind,
                      std::span<const std::string_view> types,
                      std::optional<std::string_view> fallback) {
    const std::string plural = std::string(kind) + " types";
    const MapEntry* entry = find_entry(entries, "type");
    if (!entry) {
        if (fallback) return std::string(*fallback);
        throw source.error_at(node, std::string(kind) + " is missing required key \"type\"",
                              {plural + " are: " + join(types)});
    }
    std::string type =
        read_string(source, entry->value, {std::string(kind), "type", entry->key_node});
    if (std::find(types.begin(), types.end(), type) == types.end()) {
        throw unknown_name(source, entry->value, std::string(kind) + " type", plural, type, types);
    }
    return type;
}

// --- MapReader ---

MapReader::MapReader(const YamlSource& source, const YAML::Node& node,
                     std::vector<MapEntry> entries, std::string what,
                     std::vector<std::string_view> keys, TypeKey type_key)
    : source_(source),
      node_(node),
      entries_(std::move(entries)),
      what_(std::move(what)),
      keys_(std::move(keys)) {
    std::sort(keys_.begin(), keys_.end());
    std::vector<std::string_view> listed;
    for (const std::string_view key : keys_) {
        if (key != "type" || type_key == TypeKey::listed) listed.push_back(key);
    }
    for (const MapEntry& entry : entries_) {
        if (std::binary_search(keys_.begin(), keys_.end(), entry.key)) continue;
        throw source_.error_at(
            entry.key_node, what_ + " does not use key " + quote(entry.key),
            {what_ + " accepts: " + join(listed) + did_you_mean(entry.key, listed)});
    }
}

MapReader::MapReader(const YamlSource& source, const YAML::Node& node, const Field& field,
                     std::string what, std::vector<std::string_view> keys, TypeKey type_key)
    : MapReader(source, node, read_map(source, node, field), std::move(what), std::move(keys),
                type_key) {}

namespace {

std::vector<std::string_view> with(std::vector<std::string_view> keys,
                                   const std::vector<std::string_view>& more) {
    keys.insert(keys.end(), more.begin(), more.end());
    return keys;
}

// An integer key's schema range; its open upper end is the largest int.
IntRange int_range(const Range& range) {
    const double max = std::min(range.max, double(std::numeric_limits<int>::max()));
    return {std::int64_t(range.min), std::int64_t(max)};
}

}  // namespace

MapReader::MapReader(const YamlSource& source, const YAML::Node& node,
                     std::vector<MapEntry> entries, std::string what, const EntitySchema& schema,
                     std::vector<std::string_view> more)
    : MapReader(source, node, std::move(entries), std::move(what), with(schema.key_names(), more)) {
    schema_ = &schema;
}

MapReader::MapReader(const YamlSource& source, const YAML::Node& node, const Field& field,
                     std::string what, const EntitySchema& schema,
                     std::vector<std::string_view> more)
    : MapReader(source, node, read_map(source, node, field), std::move(what), schema,
                std::move(more)) {}

Field MapReader::field(std::string_view key) const {
    const MapEntry* entry = find(key);
    return {what_, std::string(key), entry ? entry->key_node : YAML::Node()};
}

const MapEntry* MapReader::find(std::string_view key) const { return find_entry(entries_, key); }

const MapEntry& MapReader::require(std::string_view key) const {
    if (const MapEntry* entry = find(key)) return *entry;
    throw source_.error_at(node_, what_ + " is missing required key " + quote(key));
}

float MapReader::number(std::string_view key, Range range, std::optional<float> fallback) const {
    if (fallback && !has(key)) return *fallback;
    return read_number(source_, require(key).value, field(key), range);
}

float MapReader::number(std::string_view key) const {
    if (!schema_) throw std::logic_error(what_ + " is read without a schema");
    const KeySchema& k = schema_->key(key);
    const std::optional<float> fallback = k.number_default();
    if (!has(key) && !fallback && !k.required())
        throw std::logic_error(std::string(key) + "'s default is not a number: use number_or");
    return number(key, k.range, fallback);
}

float MapReader::number_or(std::string_view key, float fallback) const {
    if (!schema_) throw std::logic_error(what_ + " is read without a schema");
    return number(key, schema_->key(key).range, fallback);
}

int MapReader::integer(std::string_view key) const {
    if (!schema_) throw std::logic_error(what_ + " is read without a schema");
    const KeySchema& k = schema_->key(key);
    const std::optional<float> fallback = k.number_default();
    if (!has(key) && !fallback && !k.required())
        throw std::logic_error(std::string(key) + "'s default is not a number");
    return integer(key, int_range(k.range),
                   fallback ? std::optional<int>(int(*fallback)) : std::nullopt);
}

int MapReader::integer_or(std::string_view key, int fallback) const {
    if (!schema_) throw std::logic_error(what_ + " is read without a schema");
    return integer(key, int_range(schema_->key(key).range), fallback);
}

int MapReader::integer(std::string_view key, IntRange range, std::optional<int> fallback) const {
    if (fallback && !has(key)) return *fallback;
    return int(read_integer(source_, require(key).value, field(key), range));
}

bool MapReader::boolean(std::string_view key, bool fallback) const {
    const MapEntry* entry = find(key);
    return entry ? read_bool(source_, entry->value, field(key)) : fallback;
}

Point3 MapReader::point(std::string_view key, std::optional<Point3> fallback) const {
    if (fallback && !has(key)) return *fallback;
    return read_point(source_, require(key).value, field(key));
}

Vector3 MapReader::vector(std::string_view key, std::optional<Vector3> fallback) const {
    if (fallback && !has(key)) return *fallback;
    return read_vector(source_, require(key).value, field(key));
}

Vector3 MapReader::direction(std::string_view key, std::optional<Vector3> fallback) const {
    const Vector3 v = vector(key, fallback);
    if (const auto unit = unit_vector(v)) return *unit;
    const MapEntry* entry = find(key);
    throw source_.error_at(
        entry ? entry->value : node_,
        what_ + " " + std::string(key) + " must be non-zero, got " + format_vector(v));
}

Color MapReader::color(std::string_view key, std::optional<Color> fallback) const {
    if (fallback && !has(key)) return *fallback;
    return read_color(source_, require(key).value, field(key));
}

std::string MapReader::choice(std::string_view key, std::span<const std::string_view> names,
                              std::string_view kind, std::string_view plural,
                              std::string_view fallback) const {
    const MapEntry* entry = find(key);
    if (!entry) return std::string(fallback);
    std::string name = read_string(source_, entry->value, field(key));
    if (std::find(names.begin(), names.end(), name) == names.end()) {
        throw unknown_name(source_, entry->value, kind, plural, name, names);
    }
    return name;
}

}  // namespace glint
