// glint's command line, parsed where the other verbs' options are: the command-line library is
// compiled once, for glint and glint-mpi together.
#pragma once

namespace glint::cli {

// Parses the command line and runs the verb it asks for; the exit status.
int run_glint_command_line(int argc, char** argv);

}  // namespace glint::cli
