// Loads the scene as `glint render` does, traces the one sample with a recorder, writes the tree.
#include "explain_command.h"

#include <charconv>
#include <cstdio>
#include <limits>

#include "command_errors.h"
#include "frame_sequence.h"
#include "glint/image/atomic_file.h"
#include "glint/image/file_io.h"
#include "glint/render/explain/explain.h"
#include "glint/render/explain/ray_tree_formats.h"
#include "glint/render/world.h"
#include "glint/scene/animation.h"
#include "glint/scene/integrator_fit.h"
#include "glint/scene/load_scene.h"
#include "output_path.h"
#include "usage_error.h"
#include "whole_number_option.h"

namespace glint::cli {

namespace {

// "X,Y" as two whole numbers, or a UsageError that shows what was given.
std::pair<int, int> parse_pixel(const std::string& text) {
    const std::size_t comma = text.find(',');
    int x = -1, y = -1;
    const auto whole = [](std::string_view part, int& value) {
        const auto [end, error] = std::from_chars(part.data(), part.data() + part.size(), value);
        return error == std::errc() && end == part.data() + part.size() && value >= 0;
    };
    if (comma == std::string::npos || !whole(std::string_view(text).substr(0, comma), x) ||
        !whole(std::string_view(text).substr(comma + 1), y))
        throw UsageError{
            "--pixel: expected X,Y, two whole numbers from 0 (0,0 is the top left), "
            "got \"" +
            text + "\""};
    return {x, y};
}

void write_output(const std::string& file, const std::string& text) {
    if (file.empty()) {
        std::fwrite(text.data(), 1, text.size(), stdout);
        return;
    }
    write_file_atomically(file, [&](const std::filesystem::path& temporary) {
        UniqueFile out = open_file(temporary, "wb");
        write_bytes(out.get(), text.data(), text.size(), temporary);
        close_written_file(std::move(out), temporary);
    });
}

}  // namespace

CLI::App* add_explain_command(CLI::App& app, ExplainCommand& c) {
    CLI::App* explain = app.add_subcommand(
        "explain", "Show the ray tree of one sample of one pixel, with every term's numbers");
    explain->add_option("scene", c.scene, "Scene file, as for glint render")->required();
    explain->add_option("--pixel", c.pixel, "The pixel, X,Y from 0,0 at the top left")
        ->type_name("X,Y")
        ->required();
    explain->add_option("--sample", c.sample, "Which of the pixel's samples (from 0)")
        ->check(whole_number(0, kMaxSamplesPerPixel - 1));
    explain
        ->add_option("--frame", c.frame,
                     "The frame of an animated scene, as glint render names it (from 0)")
        ->check(whole_number(0, kMaxFrames - 1));
    explain->add_option("--seed", c.seed, "Seed of the random numbers, as given to glint render")
        ->check(whole_number<std::uint64_t>(0, std::numeric_limits<std::uint64_t>::max()));
    explain->add_option("--format", c.format, "text (an indented tree), json or dot (Graphviz)")
        ->check(CLI::IsMember({"text", "json", "dot"}));
    explain->add_option("-o,--output", c.output, "Write the tree here; default: standard output");
    add_image_options(*explain, c.image);
    add_scene_read_options(*explain, c.reading);
    return explain;
}

int run_explain(const ExplainCommand& command) {
    return reporting_errors([&] {
        const auto [x, y] = parse_pixel(command.pixel);
        if (!command.output.empty()) {
            if (const auto reason = unwritable_reason(command.output)) throw UsageError{*reason};
        }
        Scene scene = load_scene(command.scene, command.reading.load_options());
        if (command.frame > 0) {
            check_frame(scene, command.frame, "--frame");
            scene = scene_at_frame(scene, command.frame);
        }
        for (const std::string& warning : scene.warnings)
            std::fprintf(stderr, "glint: warning: %s\n", warning.c_str());
        apply_image_options(command.image, scene.settings);
        check_integrator_fits(scene);
        const PixelSample which{x, y, command.sample, command.seed};
        // Before the world is built: a bad pixel should fail at once.
        check_explainable(scene.settings, which);
        const World world(std::move(scene));
        const RayTree tree = explain(world, which);
        const std::string text = command.format == "json"  ? ray_tree_json(tree)
                                 : command.format == "dot" ? ray_tree_dot(tree)
                                                           : ray_tree_text(tree);
        write_output(command.output, text);
        return 0;
    });
}

}  // namespace glint::cli
