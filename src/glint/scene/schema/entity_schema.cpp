// Looking up the schema tables, and writing one as the docs' key table.
#include "glint/scene/schema/entity_schema.h"

#include <algorithm>
#include <charconv>
#include <stdexcept>

#include "glint/scene/schema/schema_tables.h"

namespace glint {

std::optional<float> KeySchema::number_default() const {
    float value = 0;
    const char* end = fallback.data() + fallback.size();
    const auto [ptr, ec] = std::from_chars(fallback.data(), end, value);
    if (ec != std::errc() || ptr != end) return std::nullopt;
    return value;
}

const KeySchema& EntitySchema::key(std::string_view wanted) const {
    for (const KeySchema& k : keys)
        if (k.key == wanted) return k;
    throw std::logic_error("the schema of " + std::string(name) + " has no key " +
                           std::string(wanted));
}

std::vector<std::string_view> EntitySchema::key_names() const {
    std::vector<std::string_view> names;
    for (const KeySchema& k : keys) names.push_back(k.key);
    return names;
}

std::span<const EntitySchema> entity_schemas() {
    static const std::vector<EntitySchema> all = [] {
        std::vector<EntitySchema> schemas = shape_schemas();
        for (auto family : {light_schemas(), material_schemas()})
            schemas.insert(schemas.end(), family.begin(), family.end());
        return schemas;
    }();
    return all;
}

const EntitySchema& entity_schema(EntityFamily family, std::string_view name) {
    for (const EntitySchema& schema : entity_schemas())
        if (schema.family == family && schema.name == name) return schema;
    throw std::logic_error("no schema for " + std::string(name));
}

std::vector<std::string_view> entity_names(EntityFamily family) {
    std::vector<std::string_view> names;
    for (const EntitySchema& schema : entity_schemas())
        if (schema.family == family) names.push_back(schema.name);
    std::sort(names.begin(), names.end());
    return names;
}

std::string markdown_key_table(const EntitySchema& schema) {
    std::string table = "| key | type | default | meaning | allowed |\n|---|---|---|---|---|\n";
    for (const KeySchema& k : schema.keys) {
        table += "| `" + std::string(k.key) + "` | " + std::string(k.type) + " | " +
                 std::string(k.fallback) + " | " + std::string(k.meaning) + " |";
        table += k.allowed.empty() ? " |\n" : " " + std::string(k.allowed) + " |\n";
    }
    return table;
}

}  // namespace glint
