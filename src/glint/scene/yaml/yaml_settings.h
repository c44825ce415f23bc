// The `image` and `camera` sections of the YAML format.
#pragma once

#include <string>
#include <vector>

#include "glint/camera/camera_spec.h"
#include "glint/scene/scene.h"
#include "glint/scene/yaml/yaml_map_reader.h"

namespace glint {

RenderSettings read_image(const YamlSource& source, const YAML::Node& node, const Field& field,
                          const SceneLimits& limits);
// `animation: {frames, fps}`.
Animation read_animation(const YamlSource& source, const YAML::Node& node, const Field& field);
// Keys that do nothing (a lens's shape on a pinhole camera) add a warning to `warnings`.
CameraSpec read_camera(const YamlSource& source, const YAML::Node& node, const Field& field,
                       std::vector<std::string>& warnings);

}  // namespace glint
