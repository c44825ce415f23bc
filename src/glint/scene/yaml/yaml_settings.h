// The `image` and `camera` sections of the YAML format.
#pragma once

#include "glint/camera/camera_spec.h"
#include "glint/scene/scene.h"
#include "glint/scene/yaml/yaml_map_reader.h"

namespace glint {

RenderSettings read_image(const YamlSource& source, const YAML::Node& node, const Field& field,
                          const SceneLimits& limits);
CameraSpec read_camera(const YamlSource& source, const YAML::Node& node, const Field& field);

}  // namespace glint
