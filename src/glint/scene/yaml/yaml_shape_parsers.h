// The parser of each object type, for the type table in yaml_shapes.cpp. Each reads a map whose
// keys have been checked against the table and reports degenerate shapes as errors.
// Internal to glint_scene.
#pragma once

#include "glint/geometry/shape.h"
#include "glint/scene/yaml/yaml_map_reader.h"
#include "glint/scene/yaml/yaml_shape_reader.h"

namespace glint {

// yaml_basic_shapes.cpp
Shape parse_sphere(const MapReader& object, ShapeReader& shapes);
Shape parse_plane(const MapReader& object, ShapeReader& shapes);
Shape parse_triangle(const MapReader& object, ShapeReader& shapes);
Shape parse_box(const MapReader& object, ShapeReader& shapes);
Shape parse_polygon(const MapReader& object, ShapeReader& shapes);
Shape parse_prism(const MapReader& object, ShapeReader& shapes);
Shape parse_lathe(const MapReader& object, ShapeReader& shapes);

// yaml_round_shapes.cpp
Shape parse_disk(const MapReader& object, ShapeReader& shapes);
Shape parse_cylinder(const MapReader& object, ShapeReader& shapes);
Shape parse_cone(const MapReader& object, ShapeReader& shapes);
Shape parse_torus(const MapReader& object, ShapeReader& shapes);
Shape parse_quadric(const MapReader& object, ShapeReader& shapes);

// yaml_implicit_shapes.cpp
Shape parse_implicit(const MapReader& object, ShapeReader& shapes);
Shape parse_julia(const MapReader& object, ShapeReader& shapes);
Shape parse_mandelbulb(const MapReader& object, ShapeReader& shapes);

// yaml_compound_shapes.cpp
Shape parse_csg(CsgOperation op, const MapReader& object, ShapeReader& shapes);
Shape parse_instance(const MapReader& object, ShapeReader& shapes);
Shape parse_mesh(const MapReader& object, ShapeReader& shapes);

// A shape's own validation (describe_problem) as an error at the map.
template <typename S>
S checked(const MapReader& object, S shape) {
    if (const std::string problem = describe_problem(shape); !problem.empty()) {
        throw object.source().error_at(object.node(), problem);
    }
    return shape;
}

}  // namespace glint
