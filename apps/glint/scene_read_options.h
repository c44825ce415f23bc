// The options of the verbs that load a scene about what it may read: `--allow-read DIR`, the
// folders besides its own (glint's sandbox, docs/reliability.md), `--max-file-size SIZE`, and
// the limits on what it may ask for (`--max-pixels`, `--max-samples`, `--max-ray-depth`).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "cli_app_forward.h"
#include "glint/scene/load_scene.h"

namespace glint::cli {

struct SceneReadOptions {
    std::vector<std::string> allow_read;         // folders the scene may read besides its own
    std::optional<std::uint64_t> max_file_size;  // none: each kind of file's own limit
    SceneLimits limits;

    LoadOptions load_options() const {
        return {{allow_read.begin(), allow_read.end()}, max_file_size, limits};
    }
};

void add_scene_read_options(CLI::App& command, SceneReadOptions& options);

}  // namespace glint::cli
