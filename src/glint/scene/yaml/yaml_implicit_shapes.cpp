// Parsers of the shapes found by iteration: implicit surfaces given as an expression, and the
// quaternion Julia set and Mandelbulb fractals.
#include <memory>

#include "glint/geometry/expression.h"
#include "glint/scene/yaml/yaml_shape_parsers.h"

namespace glint {

namespace {

// Where, in the file, a character of a single-line scalar lies: its node's start plus the
// offset, plus one for an opening quote. (Escapes before the offset would shift it; expressions
// have none.)
YAML::Mark mark_in_scalar(const YamlSource& source, const YAML::Node& node, std::size_t offset) {
    YAML::Mark mark = node.Mark();
    const std::string_view line = source.line(mark.line);
    const auto column = static_cast<std::size_t>(std::max(0, mark.column));
    const bool quoted = column < line.size() && (line[column] == '"' || line[column] == '\'');
    mark.column += static_cast<int>(offset) + (quoted ? 1 : 0);
    return mark;
}

ExpressionConstants read_constants(const MapReader& object) {
    ExpressionConstants constants;
    const MapEntry* entry = object.find("constants");
    if (!entry) return constants;
    for (const MapEntry& c : read_map(object.source(), entry->value, object.field("constants"))) {
        constants.emplace(c.key,
                          read_number(object.source(), c.value, {"constants", c.key, c.key_node}));
    }
    return constants;
}

std::shared_ptr<const Expression> read_function(const MapReader& object) {
    const MapEntry& entry = object.require("function");
    const std::string text = read_string(object.source(), entry.value, object.field("function"));
    auto compiled = compile_expression(text, read_constants(object));
    if (auto* error = std::get_if<ExpressionError>(&compiled)) {
        throw object.source().error_at(mark_in_scalar(object.source(), entry.value, error->offset),
                                       static_cast<int>(std::max<std::size_t>(1, error->length)),
                                       error->message, error->notes);
    }
    return std::make_shared<const Expression>(std::move(std::get<Expression>(compiled)));
}

// Precision defaults scale with the object, so that a scene in millimetres or kilometres gets
// the same relative resolution.
float largest_extent(const Bounds3& b) { return max_component(b.diagonal()); }

}  // namespace

Shape parse_implicit(const MapReader& object, ShapeReader&) {
    ImplicitSurface surface;
    surface.region = Bounds3::of(object.point("min"), object.point("max"));
    const float extent = largest_extent(surface.region);
    if (!(extent > 0) || surface.region.diagonal().x <= 0 || surface.region.diagonal().y <= 0 ||
        surface.region.diagonal().z <= 0) {
        throw object.source().error_at(object.require("min").value,
                                       "implicit min must be less than max on every axis");
    }
    surface.f = read_function(object);
    surface.tolerance = object.number_or("tolerance", 1e-4f * extent);
    surface.max_segments = object.integer("max_segments");
    return checked(object, surface);
}

Shape parse_julia(const MapReader& object, ShapeReader&) {
    JuliaSet julia;
    const MapEntry& c = object.require("c");
    const auto items =
        read_sequence(object.source(), c.value, object.field("c"), "a quaternion [r, i, j, k]", 4);
    for (std::size_t i = 0; i < 4; ++i) {
        julia.c[i] =
            read_number(object.source(), items[i], {object.what(), "c[" + std::to_string(i) + "]"});
    }
    julia.slice_w = object.number("slice_w");
    julia.center = object.point("center", Point3{0, 0, 0});
    julia.scale = object.number("scale");
    julia.max_iterations = object.integer("iterations");
    julia.epsilon = object.number_or("epsilon", 1e-3f * julia.scale);
    julia.bailout = object.number("bailout");
    julia.max_steps = object.integer("max_steps");
    return checked(object, julia);
}

Shape parse_mandelbulb(const MapReader& object, ShapeReader&) {
    Mandelbulb bulb;
    bulb.power = object.number("power");
    bulb.center = object.point("center", Point3{0, 0, 0});
    bulb.scale = object.number("scale");
    bulb.max_iterations = object.integer("iterations");
    bulb.epsilon = object.number_or("epsilon", 1e-3f * bulb.scale);
    bulb.bailout = object.number("bailout");
    bulb.max_steps = object.integer("max_steps");
    return checked(object, bulb);
}

}  // namespace glint
