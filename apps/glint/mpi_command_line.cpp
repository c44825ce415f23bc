// glint-mpi's command line, as CLI11 parses it.
#include "mpi_command_line.h"

#include <CLI/CLI.hpp>
#include <sstream>
#include <string>

#include "command_errors.h"
#include "render_cli.h"

#ifndef GLINT_VERSION
#define GLINT_VERSION "unknown"
#endif

namespace glint::cli {
namespace {

constexpr const char* kMpiExamples = R"(
Examples:
  mpirun -np 4 glint-mpi render scenes/showcase.yaml -o showcase.exr
  mpirun --hostfile hosts -np 32 glint-mpi render big.yaml -o big.exr --checkpoint 10
  srun glint-mpi render big.yaml -o big.exr --threads 8
)";

}  // namespace

std::optional<int> parse_mpi_command_line(int argc, char** argv, bool quiet, MpiCommand& command) {
    CLI::App app{"glint-mpi: glint render across the ranks of an MPI job (mpirun, srun)"};
    app.footer(kMpiExamples);
    app.set_version_flag("--version", std::string("glint ") + GLINT_VERSION + " (glint-mpi)");
    app.require_subcommand(1);
    CLI::App* render_app = add_render_command(app, command.render);
    render_app
        ->add_option("--rank-timeout", command.rank_timeout,
                     "How long rank 0 waits for a rank that holds work before ending the job "
                     "(seconds; default 300)")
        ->check(CLI::PositiveNumber);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        std::ostringstream silent;
        const int code = quiet ? app.exit(e, silent, silent) : app.exit(e);
        return code == 0 ? 0 : kExitBadInput;
    }
    return std::nullopt;
}

}  // namespace glint::cli
