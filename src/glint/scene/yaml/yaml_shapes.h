// The object types of the YAML format: one name -> parser table, whose keys are the shapes'
// schemas (scene/schema/shape_schemas.cpp), so that a new shape is one line there (plus its parser
// and its schema).
#pragma once

#include <span>
#include <string_view>
#include <vector>

#include "glint/geometry/shape.h"
#include "glint/scene/yaml/yaml_map_reader.h"
#include "glint/scene/yaml/yaml_shape_reader.h"

namespace glint {

struct ShapeType {
    std::string_view name;
    // Reads the shape from a map whose keys have been checked; `shapes` reads nested shapes.
    Shape (*parse)(const MapReader& object, ShapeReader& shapes);
};

// Sorted by name.
std::span<const ShapeType> shape_types();
std::vector<std::string_view> shape_type_names();

}  // namespace glint
