// The entity schemas against what they drive and describe: every key table of
// docs/scene-format.md is its schema's table, the readers accept exactly the schemas' keys and
// types, numbers' ranges and defaults agree with their words, the material defaults are
// glint::Material's, and the fuzz dictionary knows every key.
#include "glint/scene/schema/entity_schema.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "glint/scene/scene_error.h"
#include "glint/scene/yaml/yaml_scene_loader.h"
#include "glint/scene/yaml/yaml_shapes.h"
#include "glint/shading/material.h"

namespace glint::entity_schema_test {
namespace {

std::string read_text(const std::string& relative) {
    std::ifstream in(std::filesystem::path(GLINT_SOURCE_DIR) / relative);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// Where the docs show a schema's table: the first table after the marker line within the
// section, or the section's first table without a marker.
struct DocPlace {
    std::string section, marker;
};

DocPlace doc_place(const EntitySchema& schema) {
    const std::string name(schema.name);
    switch (schema.family) {
        case EntityFamily::object:
            return {"\n## `objects`\n", ""};
        case EntityFamily::shape:
            if (name == "union" || name == "merge" || name == "intersection" ||
                name == "difference" || name == "clip")
                return {"\n## CSG: ", ""};
            if (name == "instance") return {"\n## Definitions and instances", ""};
            return {"\n## `objects`\n", "\n`type: " + name + "`"};
        case EntityFamily::light:
            return {"\n## `lights`\n", "\n`type: " + name + "`"};
        case EntityFamily::material:
            return {"\n## `materials`\n", ""};
        case EntityFamily::texture:
            // The noise textures share the table headed by marble's line.
            if (name == "checker" || name == "image")
                return {"\n### Textures\n", "\n`type: " + name + "`"};
            return {"\n### Textures\n", "\n`type: marble`"};
        case EntityFamily::pattern:
            return {"\n### Textures\n", name == "bump" ? "\nAnd `bump` tilts"
                                                       : "\nthe surface: in place of the number"};
    }
    return {};
}

// The table's lines, from its header to its last row, or "" when it is not found.
std::string doc_table(const std::string& doc, const DocPlace& place) {
    std::size_t at = doc.find(place.section);
    if (at == std::string::npos) return "";
    if (!place.marker.empty()) {
        at = doc.find(place.marker, at);
        if (at == std::string::npos) return "";
    }
    const std::size_t start = doc.find("\n| key |", at);
    if (start == std::string::npos) return "";
    std::size_t end = start + 1;
    while (end < doc.size() && doc[end] == '|') end = doc.find('\n', end) + 1;
    return doc.substr(start + 1, end - start - 1);
}

TEST(EntitySchema, EveryKeyTableOfTheDocsIsItsSchema) {
    const std::string doc = read_text("docs/scene-format.md");
    for (const EntitySchema& schema : entity_schemas()) {
        SCOPED_TRACE(std::string(schema.name));
        EXPECT_EQ(doc_table(doc, doc_place(schema)), markdown_key_table(schema));
    }
}

TEST(EntitySchema, TheReadersAcceptEachShapeOfTheSchemas) {
    EXPECT_EQ(shape_type_names(), entity_names(EntityFamily::shape));
    EXPECT_EQ(entity_names(EntityFamily::light),
              (std::vector<std::string_view>{"directional", "disk", "point", "rectangle", "sphere",
                                             "spot"}));
}

// A scene whose only object (or light, or material) is `map`; its error, or "" when it loads.
std::string load_error(const std::string& section, const std::string& map) {
    const std::string objects = section == "objects"
                                    ? "objects: [" + map + "]\n"
                                    : "objects: [{type: sphere, center: [0, 0, 0], radius: 1}]\n";
    std::string text = "camera: {from: [0, 0, 5], at: [0, 0, 0]}\n" + objects;
    if (section == "lights") text += "lights: [" + map + "]\n";
    try {
        parse_yaml_scene(text, "schema.yaml");
        return "";
    } catch (const SceneError& e) {
        return e.what();
    }
}

TEST(EntitySchema, AKeyOutsideTheSchemaIsRefusedWithTheSchemasKeys) {
    const std::string error =
        load_error("objects", "{type: disk, center: [0, 0, 0], radius: 1, raduis: 2}");
    EXPECT_NE(error.find("raduis"), std::string::npos) << error;
    const std::string light =
        load_error("lights", "{type: spot, position: [0, 1, 0], at: [0, 0, 0], cone: 3}");
    EXPECT_NE(light.find("cone"), std::string::npos) << light;
}

// Keys whose words bound them by another key: the reader checks the range, the shape's or
// light's own validation the rest.
const std::set<std::string> kBoundByAnotherKey = {"disk.inner_radius", "torus.major_radius",
                                                  "spot.falloff", "julia.bailout",
                                                  "mandelbulb.bailout"};

TEST(EntitySchema, RangesAndDefaultsAgreeWithTheirWords) {
    for (const EntitySchema& schema : entity_schemas()) {
        for (const KeySchema& k : schema.keys) {
            const std::string name = std::string(schema.name) + "." + std::string(k.key);
            SCOPED_TRACE(name);
            EXPECT_FALSE(k.meaning.empty());
            if (k.type == "integer") {
                // "1..30"
                const std::string words = std::to_string(std::int64_t(k.range.min)) + ".." +
                                          std::to_string(std::int64_t(k.range.max));
                EXPECT_TRUE(std::string(k.allowed).starts_with(words))
                    << k.allowed << " against " << words;
                continue;
            }
            if (k.type != "number") {
                EXPECT_TRUE(k.range.is_any()) << "a range on a key that is not a number";
                continue;
            }
            if (!k.range.is_any()) {
                // "> 0" or "in [0, 1]" as the allowed words write it: "> 0", "[0, 1]".
                std::string words = k.range.describe();
                if (words.starts_with("in ")) words = words.substr(3);
                const std::string allowed(k.allowed);
                EXPECT_TRUE(allowed.starts_with(words) || kBoundByAnotherKey.contains(name))
                    << "allowed \"" << allowed << "\" against " << words;
            }
            if (const auto fallback = k.number_default()) {
                EXPECT_TRUE(k.range.contains(*fallback));
            }
        }
    }
}

TEST(EntitySchema, NumberDefaultsReadOnlyPlainNumbers) {
    EXPECT_EQ((KeySchema{"k", "number", "0.05", "m"}).number_default(), 0.05f);
    EXPECT_EQ((KeySchema{"k", "number", "1e-4", "m"}).number_default(), 1e-4f);
    EXPECT_FALSE((KeySchema{"k", "number", "1 (white)", "m"}).number_default());
    EXPECT_FALSE((KeySchema{"k", "number", "required", "m"}).number_default());
    EXPECT_FALSE((KeySchema{"k", "number", "1e-3 × scale", "m"}).number_default());
}

TEST(EntitySchema, MaterialDefaultsAreThoseOfMaterial) {
    const EntitySchema& schema = entity_schema(EntityFamily::material, "material");
    const Material m;
    const std::pair<const char*, float> numbers[] = {
        {"ka", m.ka},           {"kd", m.kd},
        {"ks", m.ks},           {"shininess", m.shininess},
        {"reflect", m.reflect}, {"transmit", m.transmit},
        {"ior", m.ior},         {"roughness", m.roughness}};
    for (const auto& [key, value] : numbers) {
        SCOPED_TRACE(key);
        EXPECT_EQ(schema.key(key).number_default(), value);
    }
}

TEST(EntitySchema, TheFuzzDictionaryHoldsEveryKey) {
    const std::string dict = read_text("tests/fuzz/yaml_scene.dict");
    for (const EntitySchema& schema : entity_schemas()) {
        // A shape's, a light's or a texture's name is its `type` value.
        const bool typed = schema.family == EntityFamily::shape ||
                           schema.family == EntityFamily::light ||
                           schema.family == EntityFamily::texture;
        if (typed) {
            EXPECT_NE(dict.find("\"" + std::string(schema.name) + "\""), std::string::npos)
                << schema.name;
        }
        for (const KeySchema& k : schema.keys)
            EXPECT_NE(dict.find("\"" + std::string(k.key) + "\""), std::string::npos)
                << schema.name << "." << k.key;
    }
}

}  // namespace
}  // namespace glint::entity_schema_test
