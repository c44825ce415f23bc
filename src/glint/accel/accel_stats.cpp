// Summing a structure's nodes into its statistics and its SAH cost.
#include "glint/accel/accel_stats.h"

#include <algorithm>
#include <cmath>

namespace glint {

double AccelStatsTally::area_of(const Bounds3& box) {
    if (box.is_empty()) return 0;
    const double x = double(box.max.x) - box.min.x, y = double(box.max.y) - box.min.y,
                 z = double(box.max.z) - box.min.z;
    return 2 * (x * y + y * z + z * x);
}

double AccelStatsTally::chance(const Bounds3& box) const {
    if (!(root_area_ > 0) || !std::isfinite(root_area_)) return 1;
    return area_of(box) / root_area_;
}

void AccelStatsTally::interior(const Bounds3& box) {
    ++stats_.interior_nodes;
    sah_ += kSahTraversalCost * chance(box);
}

void AccelStatsTally::leaf(const Bounds3& box, int depth, std::size_t references) {
    ++stats_.leaves;
    stats_.max_depth = std::max(stats_.max_depth, depth);
    depth_sum_ += depth;
    stats_.references += references;
    sah_ += kSahIntersectionCost * double(references) * chance(box);
    if (references == 0) {
        ++stats_.empty_leaves;
        return;
    }
    const bool first = stats_.leaves - stats_.empty_leaves == 1;
    stats_.min_leaf_size = first ? references : std::min(stats_.min_leaf_size, references);
    stats_.max_leaf_size = std::max(stats_.max_leaf_size, references);
}

void AccelStatsTally::cell(const Bounds3& box, std::size_t references) {
    leaf(box, 0, references);
    sah_ += kSahTraversalCost * chance(box);
}

AccelStats AccelStatsTally::finish(std::size_t unbounded, std::size_t memory_bytes) const {
    AccelStats s = stats_;
    const std::size_t filled = s.leaves - s.empty_leaves;
    s.mean_leaf_depth = s.leaves > 0 ? depth_sum_ / double(s.leaves) : 0;
    s.mean_leaf_size = filled > 0 ? double(s.references) / double(filled) : 0;
    s.unbounded = unbounded;
    s.sah_cost = sah_ + kSahIntersectionCost * double(unbounded);
    s.memory_bytes = memory_bytes;
    return s;
}

}  // namespace glint
