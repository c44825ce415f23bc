// What `glint render`, and each rank of `glint-mpi render`, makes of a command and its loaded
// scene: the image options applied and checked, the memory the render needs checked, the world
// built, and the render's options.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "glint/cluster/frame_share.h"
#include "glint/render/render.h"
#include "glint/render/world.h"
#include "render_command.h"

namespace glint::cli {

struct RenderSetup {
    std::unique_ptr<World> world;
    RenderOptions options;
    std::vector<std::filesystem::path> files_read;  // the scene's, besides the scene file
};

// The output variables --aov asks for, refused where a render could not write them all.
AovSet requested_aovs(const RenderCommand& c);

// The scene with the command's image options, and the render's options: everything checked
// but the world, which is not built. Throws UsageError (or the checks' errors) for what cannot
// be rendered. With print_warnings, the scene's warnings go to standard error.
struct PreparedRender {
    Scene scene;
    RenderOptions options;
};
PreparedRender prepare_render(const RenderCommand& command, Scene scene, const AovSet& aovs,
                              bool print_warnings);

// prepare_render, and the world built. With print_warnings, the world's warnings go to standard
// error too.
RenderSetup set_up_render(const RenderCommand& command, Scene scene, const AovSet& aovs,
                          bool print_warnings);

// The settings and options that decide a render's image, as text: ranks of glint-mpi whose
// texts differ were given other commands.
std::string settings_text(const RenderSettings& settings, const RenderOptions& options);

// How each rank renders a frame of `scene` whole (frame_share.h), as the command asks.
FrameRendering frame_rendering(const RenderCommand& command, const Scene& scene,
                               const AovSet& aovs);

}  // namespace glint::cli
