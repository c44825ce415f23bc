// Materials and textures of the YAML format, and the table that resolves an object's material:
// a name from the top-level `materials`, an inline map, or the shared default.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "glint/scene/read_sandbox.h"
#include "glint/scene/yaml/yaml_map_reader.h"
#include "glint/shading/material.h"

namespace glint {

// A material map; `what` names it in messages (`material "glass"`). Image textures must lie
// inside the sandbox.
Material read_material(const YamlSource& source, const ReadSandbox& sandbox, const YAML::Node& node,
                       const Field& field, std::string what, std::string name);
// A texture map such as {type: checker, even: 1, odd: 0}.
Texture read_texture(const YamlSource& source, const ReadSandbox& sandbox, const YAML::Node& node,
                     const Field& field);

// Appends materials to a scene's list, and where each was read to a list beside it, and hands
// out their indices.
class MaterialTable {
public:
    // The name an object without a material gets, unless the file defines a material so named.
    static constexpr std::string_view kDefaultName = "default";

    MaterialTable(const YamlSource& source, const ReadSandbox& sandbox,
                  std::vector<Material>& materials, std::vector<TextPosition>& positions)
        : source_(source), sandbox_(sandbox), materials_(materials), positions_(positions) {}

    // Reads the top-level `materials` map of name -> material map.
    void read_named(const YAML::Node& section, const Field& field);
    // The material of objects[object_index]: `entry` is its "material" key, null when absent.
    std::uint32_t resolve(const MapEntry* entry, std::size_t object_index);
    // The material a "material" key gives (a name, or a map then called `inline_name`).
    std::uint32_t resolve_given(const MapEntry& entry, const std::string& inline_name);

    // Appends a material that no name refers to (a mesh file's own), read at `where`, and
    // returns its index.
    std::uint32_t add(Material material, TextPosition where);

private:
    const YamlSource& source_;
    const ReadSandbox& sandbox_;
    std::vector<Material>& materials_;
    std::vector<TextPosition>& positions_;  // one per material
    std::map<std::string, std::uint32_t, std::less<>> named_;
    std::optional<std::uint32_t> default_;
};

}  // namespace glint
