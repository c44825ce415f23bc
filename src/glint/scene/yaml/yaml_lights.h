// Light sources of the YAML format: point and directional lights.
#pragma once

#include "glint/scene/yaml/yaml_map_reader.h"
#include "glint/shading/light.h"

namespace glint {

// A light map such as {type: point, position: [0, 5, 0]}.
Light read_light(const YamlSource& source, const YAML::Node& node, const Field& field);

}  // namespace glint
