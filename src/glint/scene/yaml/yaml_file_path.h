// The files a YAML scene names (image textures, meshes): where they are looked for, and the
// sandbox check that refuses those outside the folders the scene may read. Internal to
// glint_scene.
#pragma once

#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <string>
#include <string_view>

#include "glint/scene/read_sandbox.h"
#include "glint/scene/yaml/yaml_source.h"

namespace glint {

// `name`, as the scene gives it at `node`, taken relative to the scene file's folder. Throws a
// SceneError at the node when the sandbox refuses the path; `what` names the file's role
// ("texture", "mesh file") in the message.
std::filesystem::path scene_file_path(const YamlSource& source, const ReadSandbox& sandbox,
                                      const YAML::Node& node, const std::string& name,
                                      std::string_view what);

}  // namespace glint
