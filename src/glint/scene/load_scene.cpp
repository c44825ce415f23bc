// The scene formats by extension: YAML, NFF (also gzipped) and the model files Assimp reads.
#include "glint/scene/load_scene.h"

#include <algorithm>
#include <string>

#include "glint/scene/mesh/model_scene.h"
#include "glint/scene/nff/nff_to_scene.h"
#include "glint/scene/scene_error.h"
#include "glint/scene/yaml/yaml_scene_loader.h"

namespace glint {

Scene load_scene(const std::filesystem::path& file) {
    std::string extension = file.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (extension == ".yaml" || extension == ".yml") return load_yaml_scene(file);
    if (extension == ".nff" || (extension == ".gz" && file.stem().extension() == ".nff"))
        return load_nff_scene(file);
    if (is_model_file(file)) return load_model_scene(file);
    throw SceneError({file.string()}, "unknown scene format \"" + extension + "\"",
                     {"scene formats are: .yaml, .yml (glint), .nff, .nff.gz (Haines' NFF), and "
                      ".obj, .ply, .gltf, .glb, .stl (models)"});
}

}  // namespace glint
