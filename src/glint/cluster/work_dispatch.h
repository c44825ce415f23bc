// Rank 0's book of a render's work across a cluster: which pieces are ready (a tile's next pass,
// once the pass before is back), handed out lowest pass first to whoever asks, and which are
// back. A slow rank holds back only the pieces it holds: work goes out on request, not by a split
// made in advance.
#pragma once

#include <set>
#include <utility>
#include <vector>

#include "glint/render/render.h"

namespace glint {

class WorkDispatch {
public:
    // The pieces left in `tile_passes` (each tile's passes done) of a render of `passes` passes.
    WorkDispatch(const std::vector<int>& tile_passes, int passes);

    // Up to `most` ready pieces, lowest pass first, now in flight.
    std::vector<WorkPiece> take(int most);
    // A piece in flight, rendered: its tile's next pass is ready.
    void finish(const WorkPiece& piece);
    // Pieces in flight, not rendered (their renderer stopped): ready again.
    void give_back(const std::vector<WorkPiece>& pieces);

    bool done() const { return left_ == 0; }
    int left() const { return left_; }  // pieces not yet finished
    int in_flight() const { return in_flight_; }
    int passes_done() const;  // the passes every tile has finished

private:
    int passes_;
    std::vector<int> next_;                // each tile's next pass
    std::set<std::pair<int, int>> ready_;  // (pass, tile)
    int left_ = 0, in_flight_ = 0;
};

}  // namespace glint
