// The keys of each kind of thing a scene describes (a shape, a light, a material, a texture), in
// one table a kind: key, type, default, range and one line of meaning. The YAML reader takes its
// keys, its numbers' ranges and their defaults from it; the key tables of docs/scene-format.md
// and the fuzz dictionary are checked against it (tests/scene/entity_schema_test.cpp). A key is
// spelled here once, and a new shape is its geometry, its schema, its parser and its tests.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "glint/scene/schema/value_range.h"

namespace glint {

struct KeySchema {
    std::string_view key;
    std::string_view type;      // as the docs name it: "number", "point", "list of 3 points"
    std::string_view fallback;  // the default as the docs write it, or "required"
    std::string_view meaning;   // one line
    std::string_view allowed;   // what is accepted, in words; empty: any value of the type
    Range range = kAnyNumber;   // numbers: what the reader accepts, as `allowed` says in words

    bool required() const { return fallback == "required"; }
    // The default when it is a plain number ("0.05", "1e-4"); nothing otherwise ("1 (white)").
    std::optional<float> number_default() const;
};

enum class EntityFamily {
    shape,     // an object's geometry, by its `type`
    object,    // the keys every object takes besides its shape's ("object")
    light,     // by its `type`
    material,  // the one material map ("material")
    texture,   // a material colour's map, by its `type`
    pattern,   // a material number's map ("value") and the bump map ("bump")
};

struct EntitySchema {
    EntityFamily family;
    std::string_view name;        // the `type` ("sphere"), or the entity's own name ("material")
    std::vector<KeySchema> keys;  // in the order that messages and the docs list them

    // The key's row; a std::logic_error when there is none (a reader asking for an undeclared
    // key is a programming error).
    const KeySchema& key(std::string_view wanted) const;
    std::vector<std::string_view> key_names() const;
};

// Every schema, grouped by family.
std::span<const EntitySchema> entity_schemas();
// The schema of one kind; a std::logic_error when there is none.
const EntitySchema& entity_schema(EntityFamily family, std::string_view name);
// The names of a family's kinds, sorted (the `type` values a reader accepts).
std::vector<std::string_view> entity_names(EntityFamily family);

// The key table as docs/scene-format.md shows it: | key | type | default | meaning | allowed |.
std::string markdown_key_table(const EntitySchema& schema);

}  // namespace glint
