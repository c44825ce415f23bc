// `glint info`: what a scene holds (counts, bounds), what its acceleration structure is made of,
// and the linter's warnings, as text for a reader or as JSON for scripts.
#pragma once

#include <string>

#include "scene_read_options.h"

namespace glint::cli {

struct InfoCommand {
    std::string scene;
    std::string accel = "bvh";  // as `glint render` builds by default
    bool json = false;
    SceneReadOptions reading;  // --allow-read, --max-file-size
};

// Registers the subcommand and its options on app; returns it (to ask whether it was chosen).
CLI::App* add_info_command(CLI::App& app, InfoCommand& command);

// Exit status: 0 when the scene loads (warnings or not), 2 on bad input (the scene, options),
// 1 on any other failure.
int run_info(const InfoCommand& command);

}  // namespace glint::cli
