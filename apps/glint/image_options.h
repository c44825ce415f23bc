// The options that override a scene's image settings, shared by the verbs that trace it
// (`render`, `explain`): an explained sample is the rendered one only under the same settings.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "glint/scene/scene.h"

namespace glint::cli {

struct ImageOptions {
    std::optional<int> width, height, spp, max_depth;
    std::string integrator;  // empty: the scene's
    std::string sampler;     // empty: the scene's (or its integrator's default)
    std::string filter;      // empty: likewise; else a filter's name with its default radius
    std::string shadows;     // empty: the scene's; else feelers or map
};

void add_image_options(CLI::App& command, ImageOptions& options);

// The options as a command line gives them, each after a space: " --width 320 --spp 4".
std::string image_options_arguments(const ImageOptions& options);

// The scene's settings with the options applied; a lone width or height keeps the scene's
// aspect ratio. Throws UsageError for an image over the limits or settings that a scene file
// could not hold either (settings_problem: a sample count the sampler cannot take, adaptive
// sampling with the regular sampler or below its min_samples, shadow maps for an integrator that
// traces its shadows).
void apply_image_options(const ImageOptions& options, RenderSettings& settings);

}  // namespace glint::cli
