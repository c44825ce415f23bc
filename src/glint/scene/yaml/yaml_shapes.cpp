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
    {"box", parse_box},
    {"clip", parse_csg_of<CsgOperation::clip>},
    {"cone", parse_cone},
    {"cylinder", parse_cylinder},
    {"difference", parse_csg_of<CsgOperation::difference>},
    {"disk", parse_disk},
    {"implicit", parse_implicit},
    {"instance", parse_instance},
    {"intersection", parse_csg_of<CsgOperation::intersection>},
    {"julia", parse_julia},
    {"lathe", parse_lathe},
    {"mandelbulb", parse_mandelbulb},
    {"merge", parse_csg_of<CsgOperation::merge>},
    {"mesh", parse_mesh},
    {"plane", parse_plane},
    {"polygon", parse_polygon},
    {"prism", parse_prism},
    {"quadric", parse_quadric},
    {"sphere", parse_sphere},
    {"torus", parse_torus},
    {"triangle", parse_triangle},
    {"union", parse_csg_of<CsgOperation::union_of>},
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
