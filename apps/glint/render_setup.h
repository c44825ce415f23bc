// What `glint render`, and each rank of `glint-mpi render`, makes of a command and its loaded
// scene: the image options applied and checked, the memory the render needs checked, the world
// built, and the render's options.
#pragma once

#include <filesystem>
#include <memory>
#include <vector>

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

// Throws UsageError (or the loaders' and checks' errors) for what cannot be rendered. With
// print_warnings, the scene's and the world's warnings go to standard error.
RenderSetup set_up_render(const RenderCommand& command, Scene scene, const AovSet& aovs,
                          bool print_warnings);

}  // namespace glint::cli
