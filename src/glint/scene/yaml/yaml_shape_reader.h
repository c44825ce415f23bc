// Reads shape maps, recursively: a shape's own keys (through the shape table), its `transform`,
// CSG operands, and instances of shapes named in the `define` section. Internal to glint_scene.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "glint/geometry/shape.h"
#include "glint/scene/mesh/model_loader.h"
#include "glint/scene/read_sandbox.h"
#include "glint/scene/yaml/yaml_map_reader.h"
#include "glint/scene/yaml/yaml_materials.h"

namespace glint {

class ShapeReader {
public:
    // Mesh files must lie inside the sandbox, and so must the files they name. CSG operands'
    // own materials go to `materials`.
    ShapeReader(const YamlSource& source, const ReadSandbox& sandbox, MaterialTable& materials)
        : source_(source), sandbox_(sandbox), materials_(materials) {}

    const YamlSource& source() const { return source_; }

    // The top-level `define` section: name -> shape map. A definition may use the ones before it.
    void read_definitions(const YAML::Node& section, const Field& field);

    struct Result {
        Shape shape;
        MapReader map;  // for the caller's extra keys
    };
    // A shape map: `type`, the type's keys, `transform`, and the caller's `extra_keys` (an
    // object's material and casts_shadow), which the caller reads from the returned map.
    Result read(const YAML::Node& node, const Field& field,
                std::vector<std::string_view> extra_keys = {});

    struct ObjectResult {
        std::vector<Shape> shapes;           // one, or one per part of a mesh file
        std::shared_ptr<const Model> model;  // the mesh file's, for its parts' materials
        MapReader map;
    };
    // An object of the scene: like read(), but a mesh file gives all its parts.
    ObjectResult read_object(const YAML::Node& node, const Field& field,
                             std::vector<std::string_view> extra_keys);

    // A CSG operand: a shape map that must describe a closed solid, unless not `solid` (the
    // surface a clip cuts), and the material (index + 1) its part of the surface shows, 0 for
    // the CSG's own; `painted`: whether its surface shows at all (not a clip's cutting shapes).
    struct Operand {
        std::shared_ptr<const Shape> shape;
        std::uint32_t material = 0;
    };
    Operand read_operand(const YAML::Node& node, const Field& field, bool solid, bool painted);

    // The shape defined under the name that `key` of the map gives (an instance's `of`).
    std::shared_ptr<const Shape> definition(const MapReader& map, std::string_view key) const;

    // The model file a mesh map names (`file`, relative to the scene file, and `crease_angle`),
    // loaded once however often it is used. Errors in the model file say where the scene
    // loads it.
    std::shared_ptr<const Model> model(const MapReader& map);
    // Warnings from the models loaded, for the scene.
    const std::vector<std::string>& warnings() const { return warnings_; }

private:
    ObjectResult read_shapes(const YAML::Node& node, const Field& field,
                             std::vector<std::string_view> extra_keys, bool all_mesh_parts);

    const YamlSource& source_;
    const ReadSandbox& sandbox_;
    MaterialTable& materials_;
    std::map<std::pair<std::string, float>, std::shared_ptr<const Model>> models_;
    std::vector<std::string> warnings_;
    std::map<std::string, std::shared_ptr<const Shape>, std::less<>> definitions_;
};

}  // namespace glint
