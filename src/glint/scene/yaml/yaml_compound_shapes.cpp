// Parsers of the shapes made of other shapes: CSG, instances of definitions, and meshes.
#include <memory>

#include "glint/scene/yaml/yaml_shape_parsers.h"

namespace glint {

// A CSG shape folds its operands from the left: difference of [a, b, c] is (a - b) - c.
Shape parse_csg(CsgOperation op, const MapReader& object, ShapeReader& shapes) {
    const MapEntry& entry = object.require("objects");
    const auto items = read_sequence(object.source(), entry.value, object.field("objects"),
                                     "a list of at least 2 objects");
    if (items.size() < 2) {
        throw object.source().error_at(
            entry.value,
            object.what() + " needs at least 2 objects, got " + std::to_string(items.size()));
    }
    const auto operand = [&](std::size_t i) {
        return shapes.read_operand(items[i], {object.what(), "objects[" + std::to_string(i) + "]"});
    };
    Shape result = Csg{op, operand(0), operand(1)};
    for (std::size_t i = 2; i < items.size(); ++i) {
        result = Csg{op, std::make_shared<const Shape>(std::move(result)), operand(i)};
    }
    return result;
}

// A defined shape placed again; `transform` moves it. The geometry is shared, not copied.
// A placed definition (itself an instance) is placed again by composing the transforms, so
// that instances of instances cost one level.
Shape parse_instance(const MapReader& object, ShapeReader& shapes) {
    auto defined = shapes.definition(object, "of");
    if (const auto* placed = std::get_if<Transformed>(defined.get())) return *placed;
    return Transformed{Transform{}, std::move(defined)};
}

// In a definition or a CSG operand a mesh is one shape: its file must hold one part. (As an
// object, ShapeReader::read_object places every part.)
Shape parse_mesh(const MapReader& object, ShapeReader& shapes) {
    const auto model = shapes.model(object);
    if (model->parts.size() != 1) {
        throw object.source().error_at(
            object.require("file").value,
            "this mesh file has " + std::to_string(model->parts.size()) +
                " parts (materials), so it can only be placed as an object",
            {"definitions and CSG operands take single-part meshes"});
    }
    return TriangleMesh{model->parts.front().mesh};
}

}  // namespace glint
