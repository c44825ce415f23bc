// The job over render(): its state kept, its merges under the job's lock so that the image can
// be resolved while it runs.
#include "glint/render/render_job.h"

#include <utility>

namespace glint {

RenderJob::RenderJob(const World& world, RenderOptions options, std::optional<RenderState> state)
    : world_(world),
      options_(std::move(options)),
      state_(state ? std::move(*state) : initial_state(world.settings(), options_)) {}

RenderResult RenderJob::run(std::function<void(const WorkPiece&)> observer) {
    return run({}, std::move(observer));
}

RenderResult RenderJob::run(std::span<const WorkPiece> work,
                            std::function<void(const WorkPiece&)> observer) {
    RenderOptions options = options_;
    options.state_mutex = &state_mutex_;
    if (observer) {
        // After the caller's own hook, if it has one.
        options.after_piece = [&, hook = options_.after_piece](int pass, int tile) {
            if (hook) hook(pass, tile);
            observer(WorkPiece{pass, tile});
        };
    }
    RenderResult result = engine_ ? engine_(world_, options, progress_, state_, work)
                                  : render(world_, options, &progress_, &state_, work);
    progress_.stop_after_pass = false;
    progress_.cancel = false;
    return result;
}

Image RenderJob::image_so_far() const {
    const std::lock_guard lock(state_mutex_);
    return resolve_image(state_);
}

RenderResult RenderJob::result_so_far() const {
    const std::lock_guard lock(state_mutex_);
    RenderResult result;
    result.image = resolve_image(state_);
    result.aovs = state_.aovs.resolve();
    result.rays = state_.rays;
    result.bad_samples = state_.bad_samples;
    return result;
}

bool RenderJob::done() const {
    return state_.passes_done() >=
           pass_count(world_.settings().samples_per_pixel, state_.pass_size);
}

}  // namespace glint
