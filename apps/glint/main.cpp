// The glint command-line tool: `glint render SCENE`, `glint explain SCENE --pixel X,Y`,
// `glint info SCENE`, `glint bench SCENE` and `glint merge PARTS...`, with --help and --version.
#include <CLI/CLI.hpp>
#include <csignal>
#include <cstdio>
#include <string>

#include "bench_command.h"
#include "explain_command.h"
#include "info_command.h"
#include "merge_command.h"
#include "render_cli.h"
#include "render_command.h"

#ifndef GLINT_VERSION
#define GLINT_VERSION "unknown"
#endif

// Whether this build has glint-mpi beside glint: CMake says when it found MPI.
#ifdef GLINT_MPI
constexpr const char* kMpiSupport = "MPI: yes, glint-mpi renders across machines (" GLINT_MPI ")";
#else
constexpr const char* kMpiSupport =
    "MPI: no, glint-mpi was not built (install Open MPI: libopenmpi-dev openmpi-bin)";
#endif

namespace {

constexpr const char* kExamples = R"(
Examples:
  glint render scenes/showcase.yaml                     writes showcase.png
  glint render scenes/showcase.yaml -o big.exr --width 1920 --spp 16
  glint render scene.yaml --threads 1 --stats stats.json --quiet
  glint render scenes/room.yaml --allow-read ~/models   the scene may read ~/models too
  glint render big.yaml -o big.exr --checkpoint 10      after Ctrl-C or a crash:
  glint render big.yaml -o big.exr --resume             continues where it stopped
  glint explain scenes/showcase.yaml --pixel 160,120    the ray tree of a pixel's sample
  glint explain scene.yaml --pixel 10,20 --format dot -o tree.dot
  glint info scenes/showcase.yaml                       counts, structure, warnings
  glint info scene.yaml --accel kdtree --json
  glint bench scene.nff --json --rays 100000           build time, Mrays/s per structure
  glint render big.yaml -o big.exr --part 3/8           writes big.exr.part3of8; when all
  glint merge big.exr.part*of8                          8 are done, writes big.exr
)";

}  // namespace

int main(int argc, char** argv) {
    // Under a file-size limit (ulimit -f) a write beyond it then fails with EFBIG, which glint
    // reports, leaving the previous file intact, instead of the signal killing glint.
    std::signal(SIGXFSZ, SIG_IGN);
    CLI::App app{
        "glint: a ray tracer that renders the classic algorithms as the textbooks "
        "state them"};
    app.footer(kExamples);
    app.set_version_flag("--version", std::string("glint ") + GLINT_VERSION + "\n" + kMpiSupport);
    app.require_subcommand(1);
    glint::cli::RenderCommand render;
    glint::cli::add_render_command(app, render);
    glint::cli::ExplainCommand explain;
    const CLI::App* explain_app = glint::cli::add_explain_command(app, explain);
    glint::cli::BenchCommand bench;
    const CLI::App* bench_app = glint::cli::add_bench_command(app, bench);
    glint::cli::InfoCommand info;
    const CLI::App* info_app = glint::cli::add_info_command(app, info);
    glint::cli::MergeCommand merge;
    const CLI::App* merge_app = glint::cli::add_merge_command(app, merge);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        // --help and --version end parsing with a success code; all else is bad usage.
        return app.exit(e) == 0 ? 0 : 2;
    }
    if (bench_app->parsed()) return glint::cli::run_bench(bench);
    if (explain_app->parsed()) return glint::cli::run_explain(explain);
    if (info_app->parsed()) return glint::cli::run_info(info);
    if (merge_app->parsed()) return glint::cli::run_merge(merge);
    return glint::cli::run_render(render);
}
