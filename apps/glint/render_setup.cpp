// From a loaded scene to a world and options, as the command asks.
#include "render_setup.h"

#include <cstdio>
#include <stdexcept>
#include <string>
#include <utility>

#include "glint/render/memory_estimate.h"
#include "glint/scene/integrator_fit.h"
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

RenderSetup set_up_render(const RenderCommand& command, Scene scene, const AovSet& aovs,
                          bool print_warnings) {
    if (print_warnings)
        for (const std::string& warning : scene.warnings)
            std::fprintf(stderr, "glint: warning: %s\n", warning.c_str());
    apply_image_options(command.image, scene.settings);
    check_integrator_fits(scene);
    if (const IntegratorKind k = scene.settings.integrator;
        !aovs.list().empty() && !traces_rays(k)) {
        const std::string name(integrator_name(k));
        throw UsageError{"--aov: the output variables follow rays, and the " + name +
                         " integrator traces " + name + "s"};
    }
    const auto accel = accel_from_name(command.accel);
    if (!accel) throw UsageError{"unknown acceleration structure \"" + command.accel + "\""};
    check_memory(scene, *accel, command, aovs);
    RenderSetup setup;
    setup.files_read = scene.sources.files_read;
    ShadowAcceleration shadows;
    shadows.light_buffer = command.shadow_accel != "none";
    shadows.occluder_cache = command.shadow_accel == "light-buffer+cache";
    setup.world = std::make_unique<World>(std::move(scene), *accel, shadows);
    if (print_warnings)
        for (const std::string& warning : setup.world->warnings())
            std::fprintf(stderr, "glint: warning: %s\n", warning.c_str());
    setup.options.threads = command.threads;
    setup.options.seed = command.seed;
    setup.options.record_samples_taken = !command.samples_image.empty();
    setup.options.aovs = aovs;
    return setup;
}

}  // namespace glint::cli
