// `glint render`: load a scene, render it, write the image, and report what was traced.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "glint/cluster/frame_share.h"
#include "glint/render/render_job.h"
#include "glint/scene/scene.h"
#include "image_options.h"
#include "scene_read_options.h"

namespace glint::cli {

struct RenderCommand {
    std::string scene;
    std::string output;         // empty: the scene's name with .png, in the current directory
    ImageOptions image;         // --width, --spp, --integrator, ...
    int threads = 0;            // 0: all cores
    std::string accel = "bvh";  // an acceleration structure's name (accel_names())
    // Shadow feelers: "none", "light-buffer", or "light-buffer+cache".
    std::string shadow_accel = "none";
    std::uint64_t seed = 0;
    bool quiet = false;
    bool ppm_ascii = false;
    std::string stats_file;     // empty: none
    std::string samples_image;  // empty: none
    std::string aovs;           // --aov's list of output variables; empty: none
    SceneReadOptions reading;   // --allow-read, --max-file-size
    // The most memory the render may take beyond the loaded scene; none: what the machine has
    // available. Checked against an estimate before anything is built.
    std::optional<std::uint64_t> max_memory;
    bool resume = false;  // continue from the output's resume file
    // Write the image so far and a resume file after the first pass this long after the last.
    std::optional<double> checkpoint_minutes;
    // "I/N": render part I of N into <output>.partIofN, for glint merge; empty: the whole.
    std::string part;
    std::string split = "tiles";  // what the parts are: "tiles" or sample "passes"
    // "A..B": the frames of an animated scene to render, to an output named with '#'; empty: all
    // of them when the output is so named, else frame 0 as a still.
    std::string frames;
};

// How `glint render` loads and renders: on this process by default; glint-mpi's rank 0 shares
// the scene's files, checks the other ranks, and renders across them.
struct RenderBackend {
    std::function<Scene(const RenderCommand&)> load;                // empty: load_scene
    std::function<void(const World&, const RenderOptions&)> check;  // before the render
    RenderEngine engine;                                            // empty: this process
    // Before each image's set-up: the frame it is (0 for a still).
    std::function<void(int frame)> begin_frame;
    // Renders frames of a sequence whole, each on one of `ranks` ranks (frame_share.h), and
    // returns whether every one was done. Empty: a sequence's frames are rendered one after
    // another, each as a still is.
    std::function<bool(const std::vector<int>& frames, const FrameRendering& rendering,
                       const FrameBook& book, RenderProgress& progress)>
        share_frames;
    int ranks = 1;
};

// Renders a still, or an animation's frames one after the other (frame_sequence.h).
// Exit status: 0 on success, 2 on bad input (scene, options, an unwritable output path, a resume
// file of another render), 1 on any other failure, 130 when interrupted (after writing what was
// done to partial_output_path() and the state to resume_path(), leaving the output alone).
int run_render(const RenderCommand& command, const RenderBackend& backend = {});

}  // namespace glint::cli
