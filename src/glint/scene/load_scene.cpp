// A scene file loaded by its format's row of the table (scene_formats.h), or scene text as YAML.
#include "glint/scene/load_scene.h"

#include <string>

#include "glint/scene/read_sandbox.h"
#include "glint/scene/scene_error.h"
#include "glint/scene/scene_formats.h"
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
    const SceneFormat* format = scene_format_of(file);
    if (!format)
        throw SceneError({file.string()},
                         "unknown scene format \"" + file.extension().string() + "\"",
                         {"scene formats are: " + scene_formats_text()});
    ReadSandbox sandbox = make_read_sandbox(file, options.allow_read, options.max_file_bytes);
    sandbox.limits = options.limits;
    Scene scene = format->load(file, sandbox);
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
