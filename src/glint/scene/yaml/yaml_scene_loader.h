// The native YAML scene format (docs/scene-format.md): reads a file into a Scene.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

#include "glint/scene/read_sandbox.h"
#include "glint/scene/scene.h"
#include "glint/scene/scene_error.h"

namespace glint {

// Larger scene files are refused before they are read.
inline constexpr std::uintmax_t kMaxSceneFileBytes = std::uintmax_t(64) << 20;

// Reads and parses a scene file. Throws SceneError only; a file that cannot be read gives an
// error without a line number. The textures and meshes the scene names must lie inside the
// sandbox; without one, inside the scene's folder.
Scene load_yaml_scene(const std::filesystem::path& file, const ReadSandbox& sandbox);
Scene load_yaml_scene(const std::filesystem::path& file);

// Parses scene text; file_name is used in error locations, and its folder is where the files
// the scene names are looked for. Throws SceneError only.
Scene parse_yaml_scene(std::string_view text, const std::string& file_name,
                       const ReadSandbox& sandbox);
Scene parse_yaml_scene(std::string_view text, const std::string& file_name);

}  // namespace glint
