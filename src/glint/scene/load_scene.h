// Loading a scene file of any format glint reads, the loader picked by the file's extension, so
// that every front end (the tool, tests, bindings) loads scenes the same way.
#pragma once

#include <filesystem>

#include "glint/scene/scene.h"

namespace glint {

// .yaml and .yml (glint's format), .nff and .nff.gz (Haines' NFF), and the model files Assimp
// reads (.obj, .ply, .gltf, .glb, .stl). Throws SceneError for unknown formats and for whatever
// the loader rejects.
Scene load_scene(const std::filesystem::path& file);

}  // namespace glint
