// Picks the scene loader by the file's extension.
#pragma once

#include <filesystem>

#include "glint/scene/scene.h"

namespace glint::cli {

// Throws SceneError for unknown formats and for whatever the loader rejects.
Scene load_scene(const std::filesystem::path& file);

}  // namespace glint::cli
