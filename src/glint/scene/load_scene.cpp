// The scene formats by extension: YAML, NFF (also gzipped) and the model files Assimp reads.
#include "glint/scene/load_scene.h"

#include <algorithm>
#include <string>

#include "glint/scene/mesh/model_scene.h"
#include "glint/scene/nff/nff_to_scene.h"
#include "glint/scene/read_sandbox.h"
#include "glint/scene/scene_error.h"
#include "glint/scene/yaml/yaml_scene_loader.h"

namespace glint {

namespace {

// The files the scene read besides its own (a model scene's own is among those Assimp opened).
void note_files_read(Scene& scene, const ReadSandbox& sandbox,
                     const std::filesystem::path& own_file) {
    const auto own = resolve_path(own_file);
    for (const std::filesystem::path& read : *sandbox.files_read)
        if (read != own) scene.sources.files_read.push_back(read);
}

}  // namespace

Scene load_scene(const std::filesystem::path& file, const LoadOptions& options) {
    std::string extension = file.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    const bool yaml = extension == ".yaml" || extension == ".yml";
    const bool nff =
        extension == ".nff" || (extension == ".gz" && file.stem().extension() == ".nff");
    if (!yaml && !nff && !is_model_file(file)) {
        throw SceneError(
            {file.string()}, "unknown scene format \"" + extension + "\"",
            {"scene formats are: .yaml, .yml (glint), .nff, .nff.gz (Haines' NFF), and "
             ".obj, .ply, .gltf, .glb, .stl (models)"});
    }
    ReadSandbox sandbox = make_read_sandbox(file, options.allow_read, options.max_file_bytes);
    sandbox.limits = options.limits;
    // An NFF file names no other files: only its own size is checked.
    if (nff) return load_nff_scene(file, sandbox.file_limit(kMaxNffFileBytes), options.limits);
    Scene scene = yaml ? load_yaml_scene(file, sandbox) : load_model_scene(file, sandbox);
    note_files_read(scene, sandbox, file);
    return scene;
}

Scene parse_scene_text(std::string_view yaml_text, const std::filesystem::path& as_file,
                       const LoadOptions& options) {
    ReadSandbox sandbox = make_read_sandbox(as_file, options.allow_read, options.max_file_bytes);
    sandbox.limits = options.limits;
    Scene scene = parse_yaml_scene(yaml_text, as_file.string(), sandbox);
    note_files_read(scene, sandbox, as_file);
    return scene;
}

}  // namespace glint
