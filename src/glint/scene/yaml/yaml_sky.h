// The `sky` section of the YAML format: an image wrapped round the scene.
#pragma once

#include "glint/scene/read_sandbox.h"
#include "glint/scene/yaml/yaml_map_reader.h"
#include "glint/shading/sky.h"

namespace glint {

SkyImage read_sky(const YamlSource& source, const ReadSandbox& sandbox, const YAML::Node& node,
                  const Field& field);

}  // namespace glint
