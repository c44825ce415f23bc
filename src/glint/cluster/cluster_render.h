// One render across the ranks of a cluster. Rank 0 holds the render's state and hands out pieces
// of work (a tile's next pass) to the ranks that ask, with the tile's carry (tile_carry.h); each
// rank renders them into a film of its own and answers with the carries its pieces left and its
// counts, asking for more. Rank 0 renders too, on a thread of its own. The films' sums, which add
// in any order, are summed at rank 0 at the end and at each checkpoint. The image is the one
// process's with the same seed, bit for bit, for every integrator, adaptive sampling and output
// variables included.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "glint/cluster/transport.h"
#include "glint/render/render.h"
#include "glint/render/render_job.h"

namespace glint {

// A rank that stopped answering, or a message that makes no sense: the job cannot go on.
struct ClusterError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// What a render across ranks did, for its summary and the benchmarks.
struct ClusterStats {
    std::vector<int> pieces;  // rendered by each rank
    int sums = 0;             // times the films were summed (checkpoints and the end)
    double sum_seconds = 0;   // the time those took
    std::uint64_t bytes = 0;  // sent and received by rank 0 in messages
};

struct ClusterOptions {
    // How long rank 0 waits for a rank that holds work, or that it needs for a sum, before it
    // gives the job up.
    std::chrono::duration<double> rank_timeout{300};
    // "rank 2 (node7)", for messages; "rank 2" without it.
    std::function<std::string(int rank)> describe_rank;
    ClusterStats* stats = nullptr;  // filled in when given
};

// Rank 0: renders what is left of `state` (a fresh render's, or one resumed) with the other
// ranks, and returns the result as render() does; `progress` counts the pieces and its stop
// flags stop the job (the ranks finish the pieces they hold); options.state_mutex, if given, is
// held while results merge into the state. options.after_pass is called with
// the whole render's state (every rank's films summed) after each pass but the last, and
// options.after_piece on this thread for every piece, wherever it was rendered.
RenderResult render_as_root(const World& world, const RenderOptions& options, Transport& transport,
                            RenderState& state, const ClusterOptions& cluster,
                            RenderProgress* progress = nullptr);

// render_as_root as a render job's engine (render_job.h), on `transport`; it renders all that
// is left, and refuses a list of pieces (std::invalid_argument).
RenderEngine cluster_engine(Transport& transport, ClusterOptions cluster);

// Every other rank: renders what rank 0 hands out until it says the job is over.
void render_as_worker(const World& world, const RenderOptions& options, Transport& transport);

}  // namespace glint
