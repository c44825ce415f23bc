// The object types of the YAML format: one table from type name to keys and parser.
#include "glint/scene/yaml/yaml_shapes.h"

#include <algorithm>

#include "glint/scene/yaml/yaml_shape_parsers.h"

namespace glint {

namespace {

template <CsgOperation op>
Shape parse_csg_of(const MapReader& object, ShapeReader& shapes) {
    return parse_csg(op, object, shapes);
}

const ShapeType kShapeTypes[] = {
    {"box", {"min", "max"}, parse_box},
    {"cone", {"base", "base_radius", "apex", "apex_radius", "capped"}, parse_cone},
    {"cylinder", {"base", "top", "radius", "capped"}, parse_cylinder},
    {"difference", {"objects"}, parse_csg_of<CsgOperation::difference>},
    {"disk", {"center", "normal", "radius", "inner_radius"}, parse_disk},
    {"implicit",
     {"function", "constants", "min", "max", "tolerance", "max_segments"},
     parse_implicit},
    {"instance", {"of"}, parse_instance},
    {"intersection", {"objects"}, parse_csg_of<CsgOperation::intersection>},
    {"julia",
     {"c", "slice_w", "center", "scale", "iterations", "epsilon", "bailout", "max_steps"},
     parse_julia},
    {"mandelbulb",
     {"power", "center", "scale", "iterations", "epsilon", "bailout", "max_steps"},
     parse_mandelbulb},
    {"merge", {"objects"}, parse_csg_of<CsgOperation::merge>},
    {"mesh", {"file", "crease_angle"}, parse_mesh},
    {"plane", {"point", "normal"}, parse_plane},
    {"polygon", {"vertices", "inside_test"}, parse_polygon},
    {"quadric", {"coefficients", "min", "max"}, parse_quadric},
    {"sphere", {"center", "radius"}, parse_sphere},
    {"torus", {"center", "axis", "major_radius", "minor_radius"}, parse_torus},
    {"triangle", {"vertices", "uvs"}, parse_triangle},
    {"union", {"objects"}, parse_csg_of<CsgOperation::union_of>},
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
