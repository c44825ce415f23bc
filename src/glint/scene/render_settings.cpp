// The sampler and filter a render takes: the scene's, or its integrator's default.
#include "glint/scene/scene.h"

namespace glint {

SamplerKind sampler_of(const RenderSettings& settings) {
    if (settings.sampler) return *settings.sampler;
    // A pixel that stops early has taken a prefix of its pattern: Sobol's prefixes stay
    // stratified.
    if (settings.adaptive) return SamplerKind::sobol;
    return integrator_info(settings.integrator).sampler;
}

FilterSpec filter_of(const RenderSettings& settings) {
    if (settings.filter) return *settings.filter;
    return integrator_info(settings.integrator).filter;
}

}  // namespace glint
