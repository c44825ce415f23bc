// From a loaded scene to a world and options, as the command asks.
#include "render_setup.h"

#include <cstdio>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

#include "glint/render/memory_estimate.h"
#include "glint/render/render_choices.h"
#include "glint/scene/animation.h"
#include "glint/scene/integrator_fit.h"
#include "test_hold.h"
#include "usage_error.h"

namespace glint::cli {

namespace {

// Refuses a render whose structures, film and images would not fit, before building them.
void check_memory(const Scene& scene, AccelKind accel, const RenderCommand& c, AovSet aovs) {
    const MemoryEstimate need = estimate_render_memory(
        scene, accel,
        RenderExtras{
            .samples_image = !c.samples_image.empty(), .resuming = c.resume, .aovs = aovs});
    if (auto refusal = memory_refusal(scene, accel, need, c.max_memory, "--max-memory"))
        throw UsageError{std::move(*refusal)};
}

}  // namespace

// The output variables --aov asks for, refused where a render could not write them all.
AovSet requested_aovs(const RenderCommand& c) {
    if (c.aovs.empty()) return {};
    AovSet set;
    try {
        set = parse_aov_list(c.aovs);
    } catch (const std::invalid_argument& e) {
        throw UsageError{std::string("--aov: ") + e.what()};
    }
    if (c.resume || c.checkpoint_minutes || !c.part.empty())
        throw UsageError{
            "--aov cannot be combined with --resume, --checkpoint or --part: a resume or part "
            "file does not hold the output variables"};
    return set;
}

PreparedRender prepare_render(const RenderCommand& command, Scene scene, const AovSet& aovs,
                              bool print_warnings) {
    if (print_warnings)
        for (const std::string& warning : scene.warnings)
            std::fprintf(stderr, "glint: warning: %s\n", warning.c_str());
    apply_image_options(command.image, scene.settings);
    check_integrator_fits(scene);
    if (const auto problem = aovs_problem(aovs, scene.settings.integrator))
        throw UsageError{"--aov: " + *problem};
    PreparedRender prepared{std::move(scene), {}};
    prepared.options.threads = command.threads;
    prepared.options.seed = command.seed;
    prepared.options.record_samples_taken = !command.samples_image.empty();
    prepared.options.aovs = aovs;
    return prepared;
}

RenderSetup set_up_render(const RenderCommand& command, Scene scene, const AovSet& aovs,
                          bool print_warnings) {
    PreparedRender prepared = prepare_render(command, std::move(scene), aovs, print_warnings);
    const auto accel = accel_from_name(command.accel);
    if (!accel) throw UsageError{"unknown acceleration structure \"" + command.accel + "\""};
    check_memory(prepared.scene, *accel, command, aovs);
    RenderSetup setup;
    setup.files_read = prepared.scene.sources.files_read;
    ShadowAcceleration shadows;
    shadows.light_buffer = command.shadow_accel != "none";
    shadows.occluder_cache = command.shadow_accel == "light-buffer+cache";
    setup.world = std::make_unique<World>(std::move(prepared.scene), *accel, shadows);
    if (print_warnings)
        for (const std::string& warning : setup.world->warnings())
            std::fprintf(stderr, "glint: warning: %s\n", warning.c_str());
    setup.options = std::move(prepared.options);
    return setup;
}

std::string settings_text(const RenderSettings& s, const RenderOptions& options) {
    const FilterSpec f = filter_of(s);
    std::ostringstream out;
    out << s.width << 'x' << s.height << ' ' << s.samples_per_pixel << " spp, "
        << integrator_name(s.integrator) << ", sampler " << int(sampler_of(s)) << ", filter "
        << int(f.kind) << ' ' << f.radius << ", depth " << s.max_depth << ", adaptive "
        << (s.adaptive ? s.adaptive->threshold : 0) << ", seed " << options.seed << ", tiles "
        << options.tile_size << ", passes " << pass_size_of(s, options) << ", aovs "
        << options.aovs.list().size();
    return out.str();
}

FrameRendering frame_rendering(const RenderCommand& command, const Scene& scene,
                               const AovSet& aovs) {
    FrameRendering rendering;
    rendering.set_up = [&command, &scene, aovs](int frame) {
        RenderSetup setup = set_up_render(command, scene_at_frame(scene, frame), aovs, false);
        return FrameSetup{std::move(setup.world), std::move(setup.options)};
    };
    rendering.text = [](const World& world, const RenderOptions& options) {
        return settings_text(world.settings(), options);
    };
    rendering.hold = [](const RenderProgress& progress) {
        return test_hold_from_environment(progress);
    };
    if (command.checkpoint_minutes)
        rendering.checkpoint_every =
            std::chrono::duration<double>(*command.checkpoint_minutes * 60);
    return rendering;
}

}  // namespace glint::cli
