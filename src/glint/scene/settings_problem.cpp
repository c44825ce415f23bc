// The settings' joint checks, in the order a reader would fix them.
#include "glint/scene/settings_problem.h"

namespace glint {

std::optional<SettingsProblem> settings_problem(const RenderSettings& s) {
    const SamplerKind sampler = sampler_of(s);
    if (!is_valid_sample_count(sampler, s.samples_per_pixel))
        return SettingsProblem{"samples",
                               "samples must be a square number (1, 4, 9, 16, …) for the regular "
                               "sampler, got " +
                                   std::to_string(s.samples_per_pixel),
                               {"the jittered and sobol samplers take any number"}};
    if (s.shadows == ShadowMethod::map && s.integrator != IntegratorKind::whitted &&
        s.integrator != IntegratorKind::distributed)
        return SettingsProblem{"shadows",
                               "shadow maps are for the whitted and distributed integrators, not " +
                                   std::string(integrator_name(s.integrator)),
                               {"the physically based integrators trace their shadow rays: a "
                                "map's texels and bias would bend the light they converge to"}};
    if (s.shadows == ShadowMethod::map && s.transparent_shadows)
        return SettingsProblem{"transparent_shadows",
                               "transparent shadows need shadow feelers, not shadows: map",
                               {"a shadow map holds only the nearest surface from the light"}};
    if (!s.adaptive) return std::nullopt;
    if (integrator_info(s.integrator).traces_particles)
        return SettingsProblem{"adaptive",
                               "adaptive sampling does not apply to the " +
                                   std::string(integrator_name(s.integrator)) + " integrator",
                               {"its particles land on any pixel, so no pixel's samples tell "
                                "when it has enough"}};
    if (sampler == SamplerKind::regular)
        return SettingsProblem{"sampler",
                               "adaptive sampling needs the jittered or sobol sampler",
                               {"a pixel that stops early takes the first points of its pattern, "
                                "which for the regular grid are its top rows"}};
    if (s.samples_per_pixel < 2)
        return SettingsProblem{
            "samples",
            "adaptive sampling needs at least 2 samples a pixel, got " +
                std::to_string(s.samples_per_pixel),
            {"a pixel's error estimate needs two samples; samples is the most a pixel takes"}};
    if (s.adaptive->min_samples < 2)
        return SettingsProblem{"adaptive.min_samples",
                               "adaptive min_samples must be at least 2, got " +
                                   std::to_string(s.adaptive->min_samples),
                               {"a pixel's error estimate needs two samples"}};
    if (s.adaptive->min_samples > s.samples_per_pixel)
        return SettingsProblem{"adaptive.min_samples",
                               "adaptive min_samples (" + std::to_string(s.adaptive->min_samples) +
                                   ") exceeds the image's samples (" +
                                   std::to_string(s.samples_per_pixel) + ")",
                               {"samples is the most a pixel takes; min_samples the fewest"}};
    return std::nullopt;
}

}  // namespace glint
