// The `fog` section of the YAML format: one fog, or a list of them.
#pragma once

#include <vector>

#include "glint/scene/yaml/yaml_map_reader.h"
#include "glint/shading/fog.h"

namespace glint {

std::vector<Fog> read_fogs(const YamlSource& source, const YAML::Node& node, const Field& field);

}  // namespace glint
