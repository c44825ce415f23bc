// An animation's frames shared out whole: rank 0 hands a frame to each rank that is free (itself
// included, on a thread of its own), the rank renders it alone with all its threads, and sends
// its state back (state_transfer.h), which rank 0 writes. A frame so rendered is one process's,
// bit for bit, and has no tail, no film sum across ranks and no world built on every rank. A rank
// holding a frame says it is alive every `heartbeat`, since a frame may take far longer than the
// rank timeout; it sends its state so far at its checkpoints, and at a stop.
#pragma once

#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "glint/cluster/cluster_render.h"
#include "glint/cluster/transport.h"
#include "glint/render/render.h"
#include "glint/render/world.h"

namespace glint {

// A frame's render, set up on the rank that renders it.
struct FrameSetup {
    std::unique_ptr<World> world;
    RenderOptions options;
};

// How every rank renders a frame.
struct FrameRendering {
    // On the rank that renders `frame`, on a thread of its own: its world and options.
    std::function<FrameSetup(int frame)> set_up;
    int tile_size = RenderOptions{}.tile_size;  // every frame's
    // What decides a frame's image, as text: a rank whose text differs from rank 0's for the
    // frame was given another command, and ends the job. None: not checked.
    std::function<std::string(const World& world, const RenderOptions& options)> text;
    // The tests' hold for a frame's render (test_hold.h); none when empty.
    std::function<std::function<void(int pieces)>(const RenderProgress&)> hold;
    // After a pass, once this long has passed since the last, the state so far goes to rank 0;
    // none: never.
    std::optional<std::chrono::duration<double>> checkpoint_every;
    std::chrono::duration<double> heartbeat{10};
};

// What rank 0 does with the frames.
struct FrameBook {
    // A state of `frame`'s render before its first pass.
    std::function<RenderState(int frame)> fresh_state;
    // What decides the frame's image (FrameRendering::text), sent with it.
    std::function<std::string(int frame)> text;
    // A resumed frame's saved state; none to start it afresh.
    std::function<std::optional<RenderState>(int frame)> saved;
    // On rank 0's main thread: a frame's state as `rank` left it, every pass done or stopped.
    std::function<void(int frame, int rank, const RenderState& state, bool complete)> finished;
    // Likewise, the state of a frame in flight at a checkpoint.
    std::function<void(int frame, const RenderState& state)> checkpoint;
};

// Rank 0: renders `frames` whole, each on the first rank free, until they are done or a stop
// flag of `progress` is set (the first stops every frame in flight after its pass, the second
// at once); `finished` is called for every frame begun. The other ranks are then told that the
// frames are over. Returns whether every frame was done; fills frames_by_rank when given. A rank
// holding a frame that is silent for cluster.rank_timeout ends the job (ClusterError).
bool share_frames_as_root(Transport& transport, const std::vector<int>& frames,
                          const FrameRendering& rendering, const FrameBook& book,
                          const ClusterOptions& cluster, RenderProgress& progress,
                          std::vector<int>* frames_by_rank = nullptr);

// Every other rank: renders the frames rank 0 hands out until it says they are over.
void share_frames_as_worker(Transport& transport, const FrameRendering& rendering);

}  // namespace glint
