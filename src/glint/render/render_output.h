// What a render writes, for every front end: the image with its output variables (layers of an
// EXR file, or a PNG picture of each beside any other image), and the progress of a render that
// stops before its end (the image so far beside the output, and the state to continue from).
#pragma once

#include <chrono>
#include <filesystem>
#include <functional>

#include "glint/render/render.h"
#include "glint/render/resume_file.h"

namespace glint {

// Whether an output holds the output variables as its layers (an EXR file) rather than as
// pictures beside it.
bool holds_aov_layers(const std::filesystem::path& output);

// Where an output variable's picture goes beside a non-EXR output: "out.png" gives
// "out.depth.png".
std::filesystem::path aov_picture_path(const std::filesystem::path& output, Aov aov);

// The image, with the output variables as its layers for an EXR output; else the image and a
// picture of each variable beside it. Each file is written atomically; throws ImageError.
void write_image_and_aovs(const std::filesystem::path& output, const RenderResult& result,
                          bool ppm_ascii = false);

// The image so far at `partial` and the state at `resume`: at a checkpoint and when stopped.
// The image first: a resume file always has an image of at most its samples. Without `partial`
// the state alone (a part of a render, whose image alone is of little use).
void save_progress(const std::filesystem::path& partial, const std::filesystem::path& resume,
                   const RenderIdentity& identity, const RenderState& state, const Image& image,
                   bool ppm_ascii = false);

// Saving a render's progress while it renders, so that a crash or a kill loses at most one
// interval: at the end of each pass but the last, once `interval` has passed since the last save
// (or the start), save_progress to `partial` and `resume`.
struct CheckpointPolicy {
    std::filesystem::path partial, resume;
    RenderIdentity identity;
    std::chrono::duration<double> interval{0};
    bool ppm_ascii = false;
};

// The RenderOptions::after_pass hook that carries the policy out; its clock starts now.
std::function<void(const RenderState&)> checkpoint_hook(CheckpointPolicy policy);

}  // namespace glint
