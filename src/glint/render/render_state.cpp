// A render's state at its start: an empty film of the scene's filter, no samples.
#include "glint/render/render_state.h"

#include "glint/render/eye_sample.h"
#include "glint/render/tiles.h"

namespace glint {

RenderState::RenderState(const RenderSettings& settings, int tile_size, int pass_size_,
                         AovSet aov_set)
    : width(settings.width),
      height(settings.height),
      pass_size(pass_size_),
      working_space(settings.working_space),
      film(settings.width, settings.height, filter_of(settings),
           importance_samples_filter(settings)),
      aovs(aov_set, settings.width, settings.height, filter_of(settings),
           importance_samples_filter(settings)),
      samples(std::size_t(settings.width) * settings.height, 0),
      tile_passes(make_tiles(settings.width, settings.height, tile_size).size(), 0) {
    if (settings.adaptive) errors.resize(samples.size());
    if (integrator_info(settings.integrator).traces_particles)
        splats.emplace(settings.width, settings.height, filter_of(settings));
}

}  // namespace glint
