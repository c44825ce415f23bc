// A render as a job of the library, for every front end: the command line now, and Python, the
// browser page and MPI to come. It holds the render's state (the film, each pixel's samples,
// how far the passes got) for a world, renders what is left of it, tells an observer of each
// piece of work as it is done (a tile of a pass), stops after the pass in flight or at once
// when asked from another thread, and resolves the image so far at any time. Its state is what
// a resume file saves (resume_file.h), and a job continues from one.
#pragma once

#include <functional>
#include <mutex>
#include <optional>
#include <span>
#include <utility>

#include "glint/render/render.h"

namespace glint {

// How a job's pieces are rendered: on this process (render()), or across the ranks of a cluster
// (cluster_render.h). Renders `work` (all that is left when empty) from `state`, counting in
// `progress` and stopping at its flags, as render() does.
using RenderEngine = std::function<RenderResult(const World& world, const RenderOptions& options,
                                                RenderProgress& progress, RenderState& state,
                                                std::span<const WorkPiece> work)>;

class RenderJob {
public:
    // A render of `world`, which must outlive the job, with `options`: from its start, or from
    // `state` (read from a resume file of this render).
    RenderJob(const World& world, RenderOptions options, std::optional<RenderState> state = {});

    // Renders what is left, until every pass is done or a stop. A stop asked for before the call
    // holds for it (a front end may cancel a job whose thread has not started yet); once the
    // call returns, its stop is forgotten and the next run goes on. Calls `observer` on the render
    // thread that finished each piece, concurrently. The result's counts and time are the job's
    // totals so far.
    RenderResult run(std::function<void(const WorkPiece&)> observer = {});
    // Renders the pieces of `work` alone (render() says which lists it takes), likewise.
    RenderResult run(std::span<const WorkPiece> work,
                     std::function<void(const WorkPiece&)> observer = {});

    // From any thread while run() runs: stop once the pass in flight is done (every pixel then
    // has the same samples), or at once (tiles not yet started are skipped, those in flight
    // finish).
    void stop_after_pass() { progress_.stop_after_pass = true; }
    void cancel() { progress_.cancel = true; }
    // The counts of pieces and passes done, for a watcher thread (which may also set its stop
    // flags, as the two calls above do).
    RenderProgress& progress() { return progress_; }

    // The image of the samples taken so far: from any thread, at any time.
    Image image_so_far() const;
    // Likewise the image with the output variables of films (all but `samples`: each pixel's
    // count is the render threads' own while it runs) and the rays counted; `complete` is
    // false (done() tells, between runs).
    RenderResult result_so_far() const;
    // The state, between runs: to save in a resume file, say.
    const RenderState& state() const { return state_; }
    // Whether every pass is done.
    bool done() const;
    // Renders with `engine` from now on; render() by default.
    void set_engine(RenderEngine engine) { engine_ = std::move(engine); }

private:
    const World& world_;
    RenderOptions options_;
    RenderState state_;
    RenderProgress progress_;
    mutable std::mutex state_mutex_;  // held while tiles merge into state_ (RenderOptions)
    RenderEngine engine_;
};

}  // namespace glint
