// Parsers of the shapes made of other shapes: CSG, instances of definitions, and meshes.
#include <memory>
#include <vector>

#include "glint/scene/yaml/yaml_shape_parsers.h"

namespace glint {

namespace {

using Operand = ShapeReader::Operand;

Operand joined(CsgOperation op, const Operand& a, const Operand& b) {
    Csg csg{op, a.shape, b.shape};
    csg.material_a = a.material;
    csg.material_b = b.material;
    return {std::make_shared<const Shape>(std::move(csg))};
}

// Operands [begin, end) joined by `op` in a balanced tree: log2 of their number in levels.
Operand balanced(CsgOperation op, const std::vector<Operand>& operands, std::size_t begin,
                 std::size_t end) {
    if (end - begin == 1) return operands[begin];
    const std::size_t middle = begin + (end - begin) / 2;
    return joined(op, balanced(op, operands, begin, middle), balanced(op, operands, middle, end));
}

}  // namespace

// A CSG shape of a list of operands, nested as little as the operation allows: each level costs
// two bits of a hit's CSG path (kMaxCsgDepth). Union, merge and intersection are associative, so
// the list becomes a balanced tree; a difference of [a, b, c, ...] is a minus the merge of the
// rest, as (a - b) - c = a - (b merge c), and a clip of [a, b, c, ...] clips a by the
// intersection of the rest. A thousand operands nest ten levels.
Shape parse_csg(CsgOperation op, const MapReader& object, ShapeReader& shapes) {
    const MapEntry& entry = object.require("objects");
    const auto items = read_sequence(object.source(), entry.value, object.field("objects"),
                                     "a list of at least 2 objects");
    if (items.size() < 2) {
        throw object.source().error_at(
            entry.value,
            object.what() + " needs at least 2 objects, got " + std::to_string(items.size()));
    }
    std::vector<Operand> operands;
    operands.reserve(items.size());
    for (std::size_t i = 0; i < items.size(); ++i) {
        const bool cutting = op == CsgOperation::clip && i > 0;
        operands.push_back(
            shapes.read_operand(items[i], {object.what(), "objects[" + std::to_string(i) + "]"},
                                /*solid=*/op != CsgOperation::clip || i > 0, !cutting));
    }
    if (op == CsgOperation::difference)
        return *joined(op, operands[0], balanced(CsgOperation::merge, operands, 1, operands.size()))
                    .shape;
    if (op == CsgOperation::clip)
        return *joined(op, operands[0],
                       balanced(CsgOperation::intersection, operands, 1, operands.size()))
                    .shape;
    return *balanced(op, operands, 0, operands.size()).shape;
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
