// glint's command line: `glint render SCENE`, `glint explain SCENE --pixel X,Y`, `glint info
// SCENE`, `glint bench SCENE` and `glint merge PARTS...`, with --help and --version.
#include "glint_command_line.h"

#include <CLI/CLI.hpp>
#include <string>

#include "bench_command.h"
#include "command_errors.h"
#include "explain_command.h"
#include "info_command.h"
#include "merge_command.h"
#include "render_cli.h"
#include "render_command.h"

#ifndef GLINT_VERSION
#define GLINT_VERSION "unknown"
#endif

namespace glint::cli {
namespace {

// Whether this build has glint-mpi beside glint: CMake says when it found MPI.
#ifdef GLINT_MPI
constexpr const char* kMpiSupport = "MPI: yes, glint-mpi renders across machines (" GLINT_MPI ")";
#else
constexpr const char* kMpiSupport =
    "MPI: no, glint-mpi was not built (install Open MPI: libopenmpi-dev openmpi-bin)";
#endif

constexpr const char* kGlintExamples = R"(
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

int run_glint_command_line(int argc, char** argv) {
    CLI::App app{
        "glint: a ray tracer that renders the classic algorithms as the textbooks "
        "state them"};
    app.footer(kGlintExamples);
    app.set_version_flag("--version", std::string("glint ") + GLINT_VERSION + "\n" + kMpiSupport);
    app.require_subcommand(1);
    RenderCommand render;
    add_render_command(app, render);
    ExplainCommand explain;
    const CLI::App* explain_app = add_explain_command(app, explain);
    BenchCommand bench;
    const CLI::App* bench_app = add_bench_command(app, bench);
    InfoCommand info;
    const CLI::App* info_app = add_info_command(app, info);
    MergeCommand merge;
    const CLI::App* merge_app = add_merge_command(app, merge);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        // --help and --version end parsing with a success code; all else is bad usage.
        return app.exit(e) == 0 ? 0 : kExitBadInput;
    }
    if (bench_app->parsed()) return run_bench(bench);
    if (explain_app->parsed()) return run_explain(explain);
    if (info_app->parsed()) return run_info(info);
    if (merge_app->parsed()) return run_merge(merge);
    return run_render(render);
}

}  // namespace glint::cli
