// The options about what a scene may read, as the command line takes them.
#include "scene_read_options.h"

#include <CLI/CLI.hpp>

#include "size_option.h"
#include "whole_number_option.h"

namespace glint::cli {

void add_scene_read_options(CLI::App& command, SceneReadOptions& options) {
    // Repeatable; a folder that does not exist is bad usage (exit 2), not a scene error later.
    command
        .add_option("--allow-read", options.allow_read,
                    "Let the scene read files under DIR too (textures, meshes); it reads only "
                    "under its own folder otherwise. Repeatable")
        ->type_name("DIR")
        // Without a description of its own, the check's would read "DIR:DIR" in the help.
        ->check(CLI::Validator(CLI::ExistingDirectory).description(""))
        // One folder an occurrence, so that the scene after it is not taken for a second.
        ->expected(1)
        ->allow_extra_args(false)
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    add_size_option(command, "--max-file-size", options.max_file_size,
                    "Largest file the scene may read, itself, meshes and textures alike (textures "
                    "at most 2G); default: 64M for YAML, 1G for NFF and textures, 2G for meshes");
    const SceneLimits defaults;
    command
        .add_option("--max-pixels", options.limits.image_pixels,
                    "Most pixels the scene's image, and each image it reads, may have; default " +
                        std::to_string(defaults.image_pixels))
        ->type_name("N")
        ->check(whole_number<std::int64_t>(1, kMaxRenderPixels));
    command
        .add_option("--max-samples", options.limits.samples_per_pixel,
                    "Most samples per pixel the scene may ask for; default " +
                        std::to_string(defaults.samples_per_pixel))
        ->type_name("N")
        ->check(whole_number(1, kMaxSamplesPerPixel));
    command
        .add_option(
            "--max-ray-depth", options.limits.max_depth,
            "Deepest ray tree the scene may ask for; default " + std::to_string(defaults.max_depth))
        ->type_name("N")
        ->check(whole_number(1, kMaxDepth));
}

}  // namespace glint::cli
