// Parsers of the object types (sphere, plane, triangle, box) and their table. Each parser checks
// what makes its shape degenerate, so that the renderer never sees one.
#include "glint/scene/yaml/yaml_shapes.h"

#include <algorithm>
#include <cmath>

namespace glint {

namespace {

Shape parse_sphere(const MapReader& object, ShapeReader&) {
    return Sphere{object.point("center"), object.number("radius", kPositive)};
}

Shape parse_plane(const MapReader& object, ShapeReader&) {
    return Plane{object.point("point"), Normal3(object.direction("normal"))};
}

Shape parse_triangle(const MapReader& object, ShapeReader&) {
    const YamlSource& source = object.source();
    Triangle triangle;
    const MapEntry& vertices = object.require("vertices");
    const auto points =
        read_sequence(source, vertices.value, object.field("vertices"), "a list of 3 points", 3);
    for (std::size_t i = 0; i < 3; ++i) {
        triangle.vertices[i] =
            read_point(source, points[i], {object.what(), "vertices[" + std::to_string(i) + "]"});
    }
    if (const MapEntry* uvs = object.find("uvs")) {
        const auto pairs =
            read_sequence(source, uvs->value, object.field("uvs"), "a list of 3 [u, v] pairs", 3);
        for (std::size_t i = 0; i < 3; ++i) {
            triangle.uvs[i] =
                read_point2(source, pairs[i], {object.what(), "uvs[" + std::to_string(i) + "]"});
        }
    }
    // Twice the area over the longest edge squared is the height relative to that edge: a
    // scale-free measure of how far from a line the vertices are. Below float precision, a
    // triangle has no usable normal.
    const auto& v = triangle.vertices;
    const float longest = std::max(
        {length_squared(v[1] - v[0]), length_squared(v[2] - v[1]), length_squared(v[0] - v[2])});
    const float area2 = double_area(triangle);
    if (!std::isfinite(area2) || !std::isfinite(longest)) {
        throw source.error_at(vertices.value, "triangle is too large: its area overflows a float");
    }
    if (!(area2 > 1e-6f * longest)) {
        throw source.error_at(vertices.value,
                              "triangle vertices are collinear, so the triangle has no area");
    }
    return triangle;
}

Shape parse_box(const MapReader& object, ShapeReader&) {
    const Box box{object.point("min"), object.point("max")};
    constexpr const char* kAxes[] = {"x", "y", "z"};
    for (int axis = 0; axis < 3; ++axis) {
        if (box.min[axis] < box.max[axis]) continue;
        const std::string a = kAxes[axis];
        throw object.source().error_at(object.require("min").value,
                                       "box min must be less than max on every axis, got min." + a +
                                           " = " + format_number(box.min[axis]) + " and max." + a +
                                           " = " + format_number(box.max[axis]));
    }
    return box;
}

// A CSG shape folds its operands from the left: difference of [a, b, c] is (a - b) - c.
template <CsgOperation op>
Shape parse_csg(const MapReader& object, ShapeReader& shapes) {
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

const ShapeType kShapeTypes[] = {
    {"box", {"min", "max"}, parse_box},
    {"difference", {"objects"}, parse_csg<CsgOperation::difference>},
    {"instance", {"of"}, parse_instance},
    {"intersection", {"objects"}, parse_csg<CsgOperation::intersection>},
    {"merge", {"objects"}, parse_csg<CsgOperation::merge>},
    {"plane", {"point", "normal"}, parse_plane},
    {"sphere", {"center", "radius"}, parse_sphere},
    {"triangle", {"vertices", "uvs"}, parse_triangle},
    {"union", {"objects"}, parse_csg<CsgOperation::union_of>},
};

}  // namespace

std::span<const ShapeType> shape_types() { return kShapeTypes; }

std::vector<std::string_view> shape_type_names() {
    std::vector<std::string_view> names;
    for (const ShapeType& type : kShapeTypes) names.push_back(type.name);
    std::sort(names.begin(), names.end());  // the order notes list them in
    return names;
}

}  // namespace glint
