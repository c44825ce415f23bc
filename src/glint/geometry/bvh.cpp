// Binned-SAH construction of the BVH, depth first into a flat node array.
#include "glint/geometry/bvh.h"

#include <algorithm>
#include <cassert>

namespace glint {

namespace {

// SAH splits are tried only above this depth; below it ranges are halved by count, which needs
// at most 32 more levels for 2^32 primitives, so no leaf is deeper than kBvhMaxDepth - 2.
constexpr int kSahDepthLimit = kBvhMaxDepth - 34;
constexpr int kMaxBins = 64;

struct Bin {
    Bounds3 bounds;
    std::uint32_t count = 0;
};

class Builder {
public:
    Builder(std::span<const Bounds3> bounds, const BvhBuildOptions& options, Bvh& bvh)
        : bounds_(bounds), bvh_(bvh) {
        max_leaf_ = std::uint32_t(std::clamp(options.max_leaf_size, 1, 255));
        bins_ = std::clamp(options.bins, 2, kMaxBins);
        traversal_cost_ = options.traversal_cost;
        centroids_.reserve(bounds.size());
        for (const Bounds3& b : bounds) centroids_.push_back(b.center());
    }

    void build(std::uint32_t begin, std::uint32_t end, int depth) {
        const std::uint32_t node_index = std::uint32_t(bvh_.nodes.size());
        bvh_.nodes.emplace_back();
        Bounds3 node_bounds, centroid_bounds;
        for (std::uint32_t i = begin; i < end; ++i) {
            const std::uint32_t p = bvh_.primitive_indices[i];
            node_bounds = merge(node_bounds, bounds_[p]);
            centroid_bounds = merge(centroid_bounds, centroids_[p]);
        }
        bvh_.nodes[node_index].bounds = node_bounds;
        const std::uint32_t count = end - begin;
        if (count <= 1) return make_leaf(node_index, begin, count);

        std::uint32_t mid = begin;
        int axis = longest_axis(centroid_bounds);
        const float extent = centroid_bounds.max[axis] - centroid_bounds.min[axis];
        if (depth < kSahDepthLimit && extent > 0 && std::isfinite(extent)) {
            const auto split = sah_split(begin, end, axis, centroid_bounds, node_bounds);
            if (!split) {
                if (count <= max_leaf_) return make_leaf(node_index, begin, count);
            } else {
                mid = *split;
            }
        } else if (count <= max_leaf_) {
            return make_leaf(node_index, begin, count);
        }
        if (mid == begin || mid == end) mid = median_split(begin, end, axis);

        bvh_.nodes[node_index].axis = std::uint8_t(axis);
        build(begin, mid, depth + 1);
        bvh_.nodes[node_index].offset = std::uint32_t(bvh_.nodes.size());
        build(mid, end, depth + 1);
    }

private:
    static int longest_axis(const Bounds3& b) {
        const Vector3 d = b.diagonal();
        // Written so that a NaN extent never wins.
        int axis = 0;
        if (d.y > d[axis]) axis = 1;
        if (d.z > d[axis]) axis = 2;
        return axis;
    }

    void make_leaf(std::uint32_t node_index, std::uint32_t begin, std::uint32_t count) {
        assert(count >= 1 && count <= 255);
        bvh_.nodes[node_index].offset = begin;
        bvh_.nodes[node_index].count = std::uint16_t(count);
    }

    int bin_of(Point3 centroid, int axis, float lo, float scale) const {
        const float f = (centroid[axis] - lo) * scale;
        // NaN and negative go to the first bin, anything past the end to the last; the float is
        // compared before the cast, which would be undefined out of range.
        if (!(f > 0)) return 0;
        return f < float(bins_ - 1) ? int(f) : bins_ - 1;
    }

    // The index where [begin, end) is partitioned by the cheapest SAH plane, or nothing when a
    // leaf is cheaper.
    std::optional<std::uint32_t> sah_split(std::uint32_t begin, std::uint32_t end, int axis,
                                           const Bounds3& centroid_bounds,
                                           const Bounds3& node_bounds) {
        std::array<Bin, kMaxBins> bins{};
        const float lo = centroid_bounds.min[axis];
        const float scale = float(bins_) / (centroid_bounds.max[axis] - lo);
        for (std::uint32_t i = begin; i < end; ++i) {
            const std::uint32_t p = bvh_.primitive_indices[i];
            Bin& bin = bins[std::size_t(bin_of(centroids_[p], axis, lo, scale))];
            bin.bounds = merge(bin.bounds, bounds_[p]);
            ++bin.count;
        }
        // cost(split after bin k) = traversal + (A_left N_left + A_right N_right) / A_node,
        // swept from both ends so that each candidate costs O(1).
        std::array<float, kMaxBins> right_cost{};
        Bounds3 acc;
        std::uint32_t n = 0;
        for (int k = bins_ - 1; k > 0; --k) {
            acc = merge(acc, bins[std::size_t(k)].bounds);
            n += bins[std::size_t(k)].count;
            right_cost[std::size_t(k - 1)] = acc.surface_area() * float(n);
        }
        acc = {};
        n = 0;
        float best_cost = kInfinity;
        int best = -1;
        for (int k = 0; k < bins_ - 1; ++k) {
            acc = merge(acc, bins[std::size_t(k)].bounds);
            n += bins[std::size_t(k)].count;
            const float cost = acc.surface_area() * float(n) + right_cost[std::size_t(k)];
            if (cost < best_cost) best_cost = cost, best = k;
        }
        const float area = node_bounds.surface_area();
        const float leaf_cost = float(end - begin);
        const float split_cost = traversal_cost_ + (area > 0 ? best_cost / area : 0);
        if (best < 0 || !(split_cost < leaf_cost)) return std::nullopt;
        const auto first = bvh_.primitive_indices.begin();
        const auto it = std::partition(first + begin, first + end, [&](std::uint32_t p) {
            return bin_of(centroids_[p], axis, lo, scale) <= best;
        });
        return std::uint32_t(it - first);
    }

    // Halves the range by count, ordered along the axis; works whatever the centroids are.
    std::uint32_t median_split(std::uint32_t begin, std::uint32_t end, int axis) {
        const std::uint32_t mid = begin + (end - begin) / 2;
        const auto first = bvh_.primitive_indices.begin();
        std::nth_element(first + begin, first + mid, first + end,
                         [&](std::uint32_t a, std::uint32_t b) {
                             // NaN compares false both ways, which nth_element tolerates only
                             // as "equal"; order it before every number to keep a strict order.
                             const float ca = centroids_[a][axis], cb = centroids_[b][axis];
                             if (std::isnan(ca) || std::isnan(cb))
                                 return std::isnan(ca) && !std::isnan(cb);
                             return ca < cb;
                         });
        return mid;
    }

    std::span<const Bounds3> bounds_;
    Bvh& bvh_;
    std::vector<Point3> centroids_;
    std::uint32_t max_leaf_ = 4;
    int bins_ = 16;
    float traversal_cost_ = 0.5f;
};

}  // namespace

Bvh build_bvh(std::span<const Bounds3> bounds, const BvhBuildOptions& options) {
    Bvh bvh;
    if (bounds.empty()) return bvh;
    assert(bounds.size() <= 0xffffffffu);
    const auto n = std::uint32_t(bounds.size());
    bvh.primitive_indices.resize(n);
    for (std::uint32_t i = 0; i < n; ++i) bvh.primitive_indices[i] = i;
    bvh.nodes.reserve(2 * std::size_t(n) - 1);
    Builder(bounds, options, bvh).build(0, n, 0);
    bvh.nodes.shrink_to_fit();
    return bvh;
}

}  // namespace glint
