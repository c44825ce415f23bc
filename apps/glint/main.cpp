// The glint command-line tool: `glint render SCENE`, `glint explain SCENE --pixel X,Y`,
// `glint info SCENE`, `glint bench SCENE` and `glint merge PARTS...`, with --help and --version.
#include <CLI/CLI.hpp>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <limits>

#include "bench_command.h"
#include "explain_command.h"
#include "glint/accel/make_aggregate.h"
#include "glint/scene/scene.h"
#include "glint/scene/scene_formats.h"
#include "info_command.h"
#include "merge_command.h"
#include "render_command.h"
#include "scene_read_options.h"
#include "size_option.h"
#include "whole_number_option.h"

#ifndef GLINT_VERSION
#define GLINT_VERSION "unknown"
#endif

namespace {

using glint::cli::whole_number;

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

void add_render_command(CLI::App& app, glint::cli::RenderCommand& c) {
    CLI::App* render = app.add_subcommand("render", "Render a scene to an image");
    render->add_option("scene", c.scene, "Scene file: " + glint::scene_formats_text())->required();
    render->add_option("-o,--output", c.output,
                       "Image to write: .png (sRGB, 8-bit), .ppm, .pfm or .exr (linear float); "
                       "default: the scene's name with .png");
    glint::cli::add_image_options(*render, c.image);
    render->add_option("--threads", c.threads, "Worker threads; 0 uses every core")
        ->check(whole_number(0, 4096));
    render->add_option("--seed", c.seed, "Seed of the random numbers (same seed, same image)")
        ->check(whole_number<std::uint64_t>(0, std::numeric_limits<std::uint64_t>::max()));
    std::vector<std::string> accels;
    for (const std::string_view name : glint::accel_names()) accels.emplace_back(name);
    render
        ->add_option("--accel", c.accel, "Acceleration structure (the image does not depend on it)")
        ->check(CLI::IsMember(accels));
    render
        ->add_option("--shadow-accel", c.shadow_accel,
                     "Shadow feelers: none (the acceleration structure alone, the default), "
                     "light-buffer, or light-buffer+cache")
        ->check(CLI::IsMember({"none", "light-buffer", "light-buffer+cache"}));
    render->add_option("--stats", c.stats_file, "Also write the render's figures as JSON here");
    render->add_option("--samples-image", c.samples_image,
                       "Also write the samples each pixel took here, as grey from none (black) "
                       "to the most (white); .exr and .pfm keep the counts themselves");
    render->add_option("--aov", c.aovs,
                       "Also write these output variables (comma-separated: depth, position, "
                       "normal, albedo, uv, object, material, emission, ambient, diffuse, "
                       "specular, reflected, refracted, tree_depth, samples, nodes, primitives; "
                       "or contributions, surface, ids, cost, all): as layers of an .exr "
                       "output, else as PNGs beside it with a colour map and a legend");
    render->add_flag("--ppm-ascii", c.ppm_ascii,
                     "Write .ppm images as ASCII (P3), not binary (P6)");
    render->add_flag("-q,--quiet", c.quiet, "No progress and no summary");
    glint::cli::add_scene_read_options(*render, c.reading);
    glint::cli::add_size_option(
        *render, "--max-memory", c.max_memory,
        "Most memory the render may take beyond the scene (its structure, film and images), "
        "checked before building them: 512M, 16G, ...; default: what the machine has free");
    render->add_flag("--resume", c.resume,
                     "Continue an interrupted render of the same scene, output and options from "
                     "the resume file beside the output (<output>.resume)");
    render
        ->add_option("--checkpoint", c.checkpoint_minutes,
                     "Every MINUTES (fractions allowed), after a pass, write the image so far "
                     "beside the output (<stem>.partial<ext>) and a resume file")
        ->type_name("MINUTES")
        ->check(CLI::PositiveNumber);
    render
        ->add_option("--part", c.part,
                     "Render part I of N (every Nth tile, or a run of sample passes) into "
                     "<output>.partIofN, for glint merge to make the image of")
        ->type_name("I/N");
    render
        ->add_option("--split", c.split,
                     "What --part's parts are: tiles (the default; any render) or sample passes "
                     "(not with adaptive sampling)")
        ->check(CLI::IsMember({"tiles", "passes"}));
}

}  // namespace

int main(int argc, char** argv) {
    // Under a file-size limit (ulimit -f) a write beyond it then fails with EFBIG, which glint
    // reports, leaving the previous file intact, instead of the signal killing glint.
    std::signal(SIGXFSZ, SIG_IGN);
    CLI::App app{
        "glint: a ray tracer that renders the classic algorithms as the textbooks "
        "state them"};
    app.footer(kExamples);
    app.set_version_flag("--version", std::string("glint ") + GLINT_VERSION);
    app.require_subcommand(1);
    glint::cli::RenderCommand render;
    add_render_command(app, render);
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
