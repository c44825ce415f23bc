// Reading shape maps through the shape table, with transforms, operands and definitions.
#include "glint/scene/yaml/yaml_shape_reader.h"

#include <algorithm>
#include <filesystem>
#include <optional>
#include <string>

#include "glint/scene/yaml/yaml_file_path.h"
#include "glint/scene/yaml/yaml_shapes.h"
#include "glint/scene/yaml/yaml_transform.h"

namespace glint {

namespace {

// Where an implicit surface (placed or not) is cut open by its box, in its own coordinates.
std::optional<Point3> implicit_cut_open(const Shape& shape) {
    if (const auto* placed = std::get_if<Transformed>(&shape))
        return implicit_cut_open(*placed->shape);
    if (const auto* implicit = std::get_if<ImplicitSurface>(&shape))
        return point_cut_open(*implicit);
    return std::nullopt;
}

// "1 camera", "3 lights".
std::string count_of(std::size_t n, const char* what) {
    return std::to_string(n) + " " + what + (n == 1 ? "" : "s");
}

// A transform on an already placed shape (an instance) composes with its placement rather than
// nesting another level.
Shape place(Shape shape, const Transform& world_from_object) {
    if (auto* placed = std::get_if<Transformed>(&shape)) {
        placed->transform =
            std::make_shared<const Transform>(world_from_object * placed->world_from_object());
        return shape;
    }
    return Transformed{world_from_object, std::make_shared<const Shape>(std::move(shape))};
}

}  // namespace

void ShapeReader::read_definitions(const YAML::Node& section, const Field& field) {
    for (const MapEntry& entry : read_map(source_, section, field)) {
        if (entry.key.empty()) throw source_.error_at(entry.key_node, "a definition needs a name");
        Result r = read(entry.value, {"define", entry.key, entry.key_node});
        definitions_.emplace(entry.key, std::make_shared<const Shape>(std::move(r.shape)));
    }
}

ShapeReader::Result ShapeReader::read(const YAML::Node& node, const Field& field,
                                      std::vector<std::string_view> extra_keys) {
    ObjectResult r = read_shapes(node, field, std::move(extra_keys), false);
    return {std::move(r.shapes.front()), std::move(r.map)};
}

ShapeReader::ObjectResult ShapeReader::read_object(const YAML::Node& node, const Field& field,
                                                   std::vector<std::string_view> extra_keys) {
    return read_shapes(node, field, std::move(extra_keys), true);
}

ShapeReader::ObjectResult ShapeReader::read_shapes(const YAML::Node& node, const Field& field,
                                                   std::vector<std::string_view> extra_keys,
                                                   bool all_mesh_parts) {
    auto entries = read_map(source_, node, field);
    const std::vector<std::string_view> names = shape_type_names();
    const std::string name = read_type(source_, node, entries, "object", names);
    const auto types = shape_types();
    const ShapeType& type = *std::find_if(types.begin(), types.end(),
                                          [&](const ShapeType& t) { return t.name == name; });
    std::vector<std::string_view> keys = {"type", "transform", "motion"};
    keys.insert(keys.end(), extra_keys.begin(), extra_keys.end());
    MapReader map(source_, node, std::move(entries), name,
                  entity_schema(EntityFamily::shape, type.name), std::move(keys));

    std::vector<Shape> shapes;
    std::shared_ptr<const Model> mesh_model;
    if (all_mesh_parts && name == "mesh") {
        mesh_model = model(map);
        for (const ModelPart& part : mesh_model->parts) shapes.push_back(TriangleMesh{part.mesh});
    } else {
        shapes.push_back(type.parse(map, *this));
    }
    if (const MapEntry* motion = map.find("motion")) {
        // Motion moves the object in its own space, then `transform` places it: world =
        // transform * motion(time), so that a keyframed rotation turns it about its own origin.
        const auto animated = read_motion(source_, motion->value, map.field("motion"));
        for (Shape& shape : shapes)
            shape = Moving{animated, std::make_shared<const Shape>(std::move(shape))};
    }
    if (const MapEntry* transform = map.find("transform")) {
        const Transform t = read_transform(source_, transform->value, map.field("transform"));
        for (Shape& shape : shapes) shape = place(std::move(shape), t);
    }
    if (const int depth = csg_depth(shapes.front()); depth > kMaxCsgDepth) {
        throw source_.error_at(
            node,
            "CSG nests " + std::to_string(depth) + " levels deep here, more than the " +
                std::to_string(kMaxCsgDepth) + " glint allows",
            {"each level takes two bits of the 64-bit record a hit keeps of the CSG operands it "
             "is on, and the cap bounds the recursion of every ray's intersection",
             "levels add up through definitions and instances; a list of n operands takes about "
             "log2 n"});
    }
    return {std::move(shapes), std::move(mesh_model), std::move(map)};
}

ShapeReader::Operand ShapeReader::read_operand(const YAML::Node& node, const Field& field,
                                               bool solid, bool painted) {
    Result r = read(node, field, {"material"});
    std::uint32_t material = 0;
    if (const MapEntry* given = r.map.find("material")) {
        if (!painted)
            throw source_.error_at(given->key_node,
                                   "a clip's cutting shapes show no surface, so no material",
                                   {"the material of the clip's first object paints it"});
        material = materials_.resolve_given(*given, "(" + field.what + " " + field.key + ")") + 1;
    }
    if (solid && !is_solid(r.shape)) {
        std::vector<std::string> notes;
        if (const auto cut = implicit_cut_open(r.shape)) {
            notes.push_back("the function is negative at " + format_vector(to_vector(*cut)) +
                            ", on the boundary of the min/max box: the box cuts the solid f < 0 "
                            "open; a box that encloses the surface makes it a solid");
        }
        notes.push_back(
            "CSG operands are solids: spheres, boxes, capped cylinders and cones, tori, prisms, "
            "closed lathes, implicit surfaces inside their box, fractals, closed meshes, planes "
            "(half-spaces), CSG "
            "shapes other than clip, and transforms and instances of these");
        throw source_.error_at(
            node, r.map.what() + " is not a closed solid, so it cannot be a CSG operand", notes);
    }
    return {std::make_shared<const Shape>(std::move(r.shape)), material};
}

std::shared_ptr<const Shape> ShapeReader::definition(const MapReader& map,
                                                     std::string_view key) const {
    const MapEntry& entry = map.require(key);
    const std::string name = read_string(source_, entry.value, map.field(key));
    if (const auto it = definitions_.find(name); it != definitions_.end()) return it->second;
    std::vector<std::string_view> names;
    for (const auto& [defined, shape] : definitions_) names.push_back(defined);
    if (names.empty()) {
        throw source_.error_at(entry.value, "unknown definition " + quote(name),
                               {"the scene has no `define` section (or the name is defined "
                                "after its use)"});
    }
    throw unknown_name(source_, entry.value, "definition", "definitions", name, names);
}

std::shared_ptr<const Model> ShapeReader::model(const MapReader& map) {
    const MapEntry& entry = map.require("file");
    const std::string name = read_string(source_, entry.value, map.field("file"));
    const std::filesystem::path file =
        scene_file_path(source_, sandbox_, entry.value, name, "mesh file");
    ModelOptions options;
    options.sandbox = sandbox_;
    if (map.has("crease_angle")) options.crease_angle_degrees = map.number("crease_angle");
    const auto key =
        std::pair{file.lexically_normal().string(), options.crease_angle_degrees.value_or(-1)};
    if (const auto it = models_.find(key); it != models_.end()) return it->second;
    if (!std::filesystem::is_regular_file(file)) {
        throw source_.error_at(entry.value, "mesh file " + quote(name) + " not found",
                               {"looked for " + file.string()});
    }
    try {
        auto model = std::make_shared<const Model>(load_model(file, options));
        // The model's warnings name its file already.
        warnings_.insert(warnings_.end(), model->warnings.begin(), model->warnings.end());
        if (!model->cameras.empty() || !model->lights.empty()) {
            // A mesh object takes triangles and materials; the scene has its own camera and
            // lights. Say so rather than drop the file's silently.
            std::string ignored = count_of(model->cameras.size(), "camera");
            if (model->cameras.empty())
                ignored = count_of(model->lights.size(), "light");
            else if (!model->lights.empty())
                ignored += " and " + count_of(model->lights.size(), "light");
            const YAML::Mark m = entry.value.Mark();
            warnings_.push_back(file.string() + ": " + ignored + " of the file ignored: as a " +
                                "mesh object (" + source_.file_name() + ":" +
                                std::to_string(m.line + 1) + ":" + std::to_string(m.column + 1) +
                                ") it gives only its triangles and materials; render the file on "
                                "its own to use them");
        }
        return models_.emplace(key, std::move(model)).first->second;
    } catch (const SceneError& e) {
        const YAML::Mark m = entry.value.Mark();
        std::vector<std::string> notes = e.notes();
        notes.push_back("the mesh is loaded by " + source_.file_name() + ":" +
                        std::to_string(m.line + 1) + ":" + std::to_string(m.column + 1));
        throw SceneError(e.location(), e.message(), std::move(notes), e.source_line(), e.span());
    }
}

}  // namespace glint
