// A model file (OBJ, PLY, glTF, STL) as a whole scene, for `glint render model.obj`: the
// file's first camera, or one that frames the model; the file's lights, or a key and a fill
// light; the file's materials.
#pragma once

#include <filesystem>

#include "glint/scene/mesh/model_loader.h"
#include "glint/scene/scene.h"

namespace glint {

Scene model_to_scene(const Model& model);

// load_model then model_to_scene. Throws SceneError only. Without a sandbox the model reads only
// under its own folder.
Scene load_model_scene(const std::filesystem::path& file, const ReadSandbox& sandbox);
Scene load_model_scene(const std::filesystem::path& file);

}  // namespace glint
