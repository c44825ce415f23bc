// `glint explain SCENE --pixel X,Y`: the ray tree of one sample of one pixel, as text, JSON or
// Graphviz DOT (docs/explain.md).
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <string>

#include "image_options.h"
#include "scene_read_options.h"

namespace glint::cli {

struct ExplainCommand {
    std::string scene;
    std::string pixel;  // "X,Y"
    int sample = 0;     // of the pixel's samples
    std::uint64_t seed = 0;
    std::string format = "text";  // text, json or dot
    std::string output;           // empty: standard output
    int frame = 0;                // of an animated scene
    ImageOptions image;           // as given to the render explained
    SceneReadOptions reading;
};

CLI::App* add_explain_command(CLI::App& app, ExplainCommand& command);

// Exit status: 0 when written, 2 on bad input (scene, options, a pixel or sample outside the
// image), 1 on any other failure.
int run_explain(const ExplainCommand& command);

}  // namespace glint::cli
