// `render` and its options on a command line: glint's and glint-mpi's.
#pragma once

#include "cli_app_forward.h"
#include "render_command.h"

namespace glint::cli {

CLI::App* add_render_command(CLI::App& app, RenderCommand& command);

}  // namespace glint::cli
