// The scene formats glint reads, in one table: their extensions, what they are, and how each is
// loaded. load_scene picks the loader from it, and the command line's help, `glint info` and the
// error for an unknown extension list it, so that a new format is one row.
#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <string_view>

#include "glint/scene/read_sandbox.h"
#include "glint/scene/scene.h"

namespace glint {

struct SceneFormat {
    std::string_view name;                         // "glint", "NFF", "model"
    std::span<const std::string_view> extensions;  // lower case, with the dot: ".yaml", ".nff.gz"
    std::string_view description;                  // one line: what it is
    // Reads the file under the sandbox (its reads and limits); throws SceneError.
    Scene (*load)(const std::filesystem::path& file, const ReadSandbox& sandbox);
};

// Every format, glint's own first.
std::span<const SceneFormat> scene_formats();

// The format whose extension the file name ends with, in any case (".NFF.GZ" too); null for none.
const SceneFormat* scene_format_of(const std::filesystem::path& file);

// The formats in a line, for help and errors: ".yaml, .yml (glint's format), .nff, .nff.gz
// (Haines' NFF), .obj, ... (models)".
std::string scene_formats_text();

}  // namespace glint
