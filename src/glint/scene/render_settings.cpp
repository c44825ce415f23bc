// The integrators' names, and the sampler and filter each takes unless the scene says otherwise.
#include "glint/scene/scene.h"

namespace glint {

namespace {
// Sorted by name, for the messages that list them.
constexpr std::string_view kIntegratorNames[] = {"distributed", "whitted"};
constexpr IntegratorKind kIntegratorKinds[] = {IntegratorKind::distributed,
                                               IntegratorKind::whitted};
}  // namespace

std::span<const std::string_view> integrator_names() { return kIntegratorNames; }

std::optional<IntegratorKind> integrator_from_name(std::string_view name) {
    for (std::size_t i = 0; i < std::size(kIntegratorNames); ++i)
        if (kIntegratorNames[i] == name) return kIntegratorKinds[i];
    return std::nullopt;
}

std::string_view integrator_name(IntegratorKind kind) {
    for (std::size_t i = 0; i < std::size(kIntegratorNames); ++i)
        if (kIntegratorKinds[i] == kind) return kIntegratorNames[i];
    return "unknown";
}

SamplerKind sampler_of(const RenderSettings& settings) {
    if (settings.sampler) return *settings.sampler;
    // A pixel that stops early has taken a prefix of its pattern: Sobol's prefixes stay
    // stratified.
    if (settings.adaptive) return SamplerKind::sobol;
    return settings.integrator == IntegratorKind::whitted ? SamplerKind::regular
                                                          : SamplerKind::jittered;
}

FilterSpec filter_of(const RenderSettings& settings) {
    if (settings.filter) return *settings.filter;
    if (settings.integrator == IntegratorKind::whitted) return FilterSpec{};
    // The notes' "stochastic sampling with Gaussian weighting".
    return {FilterKind::gaussian, default_filter_radius(FilterKind::gaussian)};
}

}  // namespace glint
