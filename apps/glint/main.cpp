// The glint command-line tool: `glint render SCENE`, `glint explain SCENE --pixel X,Y`,
// `glint info SCENE`, `glint bench SCENE` and `glint merge PARTS...`, with --help and --version.
#include <csignal>

#include "glint_command_line.h"

int main(int argc, char** argv) {
    // Under a file-size limit (ulimit -f) a write beyond it then fails with EFBIG, which glint
    // reports, leaving the previous file intact, instead of the signal killing glint.
    std::signal(SIGXFSZ, SIG_IGN);
    return glint::cli::run_glint_command_line(argc, argv);
}
