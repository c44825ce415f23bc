// glint-mpi's command line, `render` with glint render's options and --rank-timeout, parsed in
// glint_cli beside glint's own: the command-line library is compiled once for both tools.
#pragma once

#include <optional>

#include "render_command.h"

namespace glint::cli {

struct MpiCommand {
    RenderCommand render;
    double rank_timeout = 300;  // seconds rank 0 waits for a rank that holds work
};

// Parses the command line into `command`. When parsing ends the program (--help, --version, bad
// usage) returns its exit status, having printed why unless `quiet`: every rank reads the same
// command line, and rank 0 alone speaks.
std::optional<int> parse_mpi_command_line(int argc, char** argv, bool quiet, MpiCommand& command);

}  // namespace glint::cli
