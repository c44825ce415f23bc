// Ready pieces in a set ordered by pass, then tile: the order one process renders them in.
#include "glint/cluster/work_dispatch.h"

#include <algorithm>
#include <stdexcept>

namespace glint {

WorkDispatch::WorkDispatch(const std::vector<int>& tile_passes, int passes)
    : passes_(passes), next_(tile_passes) {
    for (std::size_t tile = 0; tile < next_.size(); ++tile) {
        if (next_[tile] < passes_) ready_.insert({next_[tile], int(tile)});
        left_ += std::max(0, passes_ - next_[tile]);
    }
}

std::vector<WorkPiece> WorkDispatch::take(int most) {
    std::vector<WorkPiece> pieces;
    while (int(pieces.size()) < most && !ready_.empty()) {
        const auto [pass, tile] = *ready_.begin();
        ready_.erase(ready_.begin());
        pieces.push_back({pass, tile});
    }
    in_flight_ += int(pieces.size());
    return pieces;
}

void WorkDispatch::finish(const WorkPiece& piece) {
    if (piece.tile < 0 || std::size_t(piece.tile) >= next_.size() ||
        next_[std::size_t(piece.tile)] != piece.pass)
        throw std::logic_error("WorkDispatch: a piece finished that was not in flight");
    --in_flight_;
    --left_;
    const int next = ++next_[std::size_t(piece.tile)];
    if (next < passes_) ready_.insert({next, piece.tile});
}

void WorkDispatch::give_back(const std::vector<WorkPiece>& pieces) {
    for (const WorkPiece& piece : pieces) ready_.insert({piece.pass, piece.tile});
    in_flight_ -= int(pieces.size());
}

int WorkDispatch::passes_done() const {
    return next_.empty() ? passes_ : *std::min_element(next_.begin(), next_.end());
}

}  // namespace glint
