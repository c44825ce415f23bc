// The options of `glint render`, which glint-mpi's `render` takes too.
#include "render_cli.h"

#include <CLI/CLI.hpp>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "glint/accel/make_aggregate.h"
#include "glint/scene/scene_formats.h"
#include "scene_read_options.h"
#include "size_option.h"
#include "whole_number_option.h"

namespace glint::cli {

CLI::App* add_render_command(CLI::App& app, RenderCommand& c) {
    CLI::App* render = app.add_subcommand("render", "Render a scene to an image");
    render->add_option("scene", c.scene, "Scene file: " + scene_formats_text())->required();
    render->add_option("-o,--output", c.output,
                       "Image to write: .png (sRGB, 8-bit), .ppm, .pfm or .exr (linear float); "
                       "an animation's frames where # stand (out.####.png); default: the "
                       "scene's name with .png (.####.png for an animation)");
    render
        ->add_option("--frames", c.frames,
                     "Frames of an animated scene to render, A..B or A, counted from 0; "
                     "default: all of them when the output names frames with #")
        ->type_name("A..B");
    add_image_options(*render, c.image);
    render->add_option("--threads", c.threads, "Worker threads; 0 uses every core")
        ->check(whole_number(0, 4096));
    render->add_option("--seed", c.seed, "Seed of the random numbers (same seed, same image)")
        ->check(whole_number<std::uint64_t>(0, std::numeric_limits<std::uint64_t>::max()));
    std::vector<std::string> accels;
    for (const std::string_view name : accel_names()) accels.emplace_back(name);
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
    add_scene_read_options(*render, c.reading);
    add_size_option(
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
    return render;
}

}  // namespace glint::cli
