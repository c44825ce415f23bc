// Loading a scene file of any format glint reads, the loader picked by the file's extension, so
// that every front end (the tool, tests, bindings) loads scenes the same way.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <vector>

#include "glint/scene/scene.h"

namespace glint {

struct LoadOptions {
    // Folders whose files, at any depth, the scene may read besides its own folder's (textures,
    // meshes, and the files these name). Anything else is refused: see read_sandbox.h.
    std::vector<std::filesystem::path> allow_read;
    // The largest file of any kind the scene may read, itself included; nothing: each kind's
    // own limit (docs/cli.md, "Limits").
    std::optional<std::uintmax_t> max_file_bytes;
    // What the scene may ask for (scene_limits.h).
    SceneLimits limits;
};

// Any format of scene_formats.h, picked by the file's extension: .yaml and .yml (glint's
// format), .nff and .nff.gz (Haines' NFF), and the model files Assimp reads (.obj, .ply, .gltf,
// .glb, .stl). Throws SceneError for unknown formats and for whatever
// the loader rejects, including a file the scene names outside the folders it may read. Without
// options a scene reads only under its own folder. The scene's sources.files_read lists every
// other file it read.
Scene load_scene(const std::filesystem::path& file, const LoadOptions& options = {});

// A scene in glint's YAML format given as text (Python's dict scenes, say), read as if it were
// the file `as_file`: its errors are located there, and it reads files as a scene in that
// file's folder would, under the same options.
Scene parse_scene_text(std::string_view yaml_text, const std::filesystem::path& as_file,
                       const LoadOptions& options = {});

}  // namespace glint
