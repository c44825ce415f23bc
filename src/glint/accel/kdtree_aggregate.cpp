// Building the kd-tree by an SAH sweep over presorted events, and its front-to-back traversal.
#include "glint/accel/kdtree_aggregate.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>

#include "glint/accel/mailbox.h"
#include "glint/accel/rounding_margin.h"
#include "glint/geometry/traversal_counters.h"

namespace glint {

namespace {

// A primitive's bound edge on one axis. Events of a node are sorted by position.
struct Event {
    float position;
    std::uint32_t primitive;  // local (bounded) index
    bool is_end;
};
using Events = std::array<std::vector<Event>, 3>;

Point3 with_component(Point3 p, int axis, float value) {
    (axis == 0 ? p.x : axis == 1 ? p.y : p.z) = value;
    return p;
}

struct Split {
    int axis = -1;
    float position = 0;
    float cost = kInfinity;
};

class KdTreeBuilder {
public:
    KdTreeBuilder(std::span<const Bounds3> boxes, std::span<const std::uint32_t> global,
                  const KdBuildOptions& options, std::vector<KdNode>& nodes,
                  std::vector<std::uint32_t>& leaf_primitives)
        : boxes_(boxes),
          global_(global),
          options_(options),
          nodes_(nodes),
          leaf_primitives_(leaf_primitives),
          side_(boxes.size(), 0) {
        const double n = double(boxes.size());
        max_depth_ = options.max_depth >= 0
                         ? options.max_depth
                         : int(std::lround(8 + 1.3 * std::log2(std::max(n, 1.0))));
        max_depth_ = std::clamp(max_depth_, 0, kKdMaxDepth - 1);
        reference_budget_ = double(options.max_references_per_primitive) * n + 4096;
    }

    int deepest() const { return deepest_; }

    // Events of the node's primitives, sorted by position on each axis; consumed.
    void build(const Bounds3& node_bounds, Events events, int depth, int bad_refines) {
        const std::size_t count = events[0].size() / 2;
        const std::uint32_t node_index = std::uint32_t(nodes_.size());
        nodes_.emplace_back();
        deepest_ = std::max(deepest_, depth);
        if (count <= std::size_t(options_.max_leaf_size) || depth >= max_depth_ ||
            double(references_) > reference_budget_)
            return make_leaf(node_index, events[0]);

        // pbrt-v3's termination: a split that costs more than the leaf counts as a bad refine;
        // three on one path, or a clearly worse split for a small node, make a leaf.
        const Split split = best_split(node_bounds, events, count);
        const float leaf_cost = options_.intersection_cost * float(count);
        if (split.cost > leaf_cost) ++bad_refines;
        if (split.axis < 0 || (split.cost > 4 * leaf_cost && count < 16) || bad_refines >= 3)
            return make_leaf(node_index, events[0]);

        // Below: bounds start before the plane; above: bounds end after it; straddlers both.
        for (const Event& e : events[std::size_t(split.axis)])
            if (!e.is_end) side_[e.primitive] = e.position < split.position ? 1 : 0;
        for (const Event& e : events[std::size_t(split.axis)])
            if (e.is_end && e.position > split.position) side_[e.primitive] |= 2;
        Events below, above;
        for (std::size_t a = 0; a < 3; ++a) {
            for (const Event& e : events[a]) {
                const std::uint8_t side = side_[e.primitive];
                if (side != 2) below[a].push_back(e);  // 0 cannot happen: bounds have extent
                if (side & 2) above[a].push_back(e);
            }
            events[a] = {};  // free the parent's lists before recursing
        }
        nodes_[node_index] = KdNode::interior(split.axis, split.position);
        build({node_bounds.min, with_component(node_bounds.max, split.axis, split.position)},
              std::move(below), depth + 1, bad_refines);
        nodes_[node_index].set_above_child(std::uint32_t(nodes_.size()));
        build({with_component(node_bounds.min, split.axis, split.position), node_bounds.max},
              std::move(above), depth + 1, bad_refines);
    }

private:
    // The cheapest plane among the bound edges strictly inside the node, on all three axes:
    // cost = traversal + intersection (1 - bonus) (P_below N_below + P_above N_above), with P
    // the children's surface areas relative to the node's (MacDonald and Booth 1990).
    Split best_split(const Bounds3& node_bounds, const Events& events, std::size_t count) const {
        Split best;
        const Vector3 extent = node_bounds.diagonal();
        const float inv_area = 1 / node_bounds.surface_area();
        for (int axis = 0; axis < 3; ++axis) {
            const float lo = node_bounds.min[axis], hi = node_bounds.max[axis];
            const float e1 = extent[(axis + 1) % 3], e2 = extent[(axis + 2) % 3];
            const auto& list = events[std::size_t(axis)];
            // At a plane p: N_below counts bounds with min < p, N_above those with max > p.
            std::size_t below = 0, above = count;
            for (std::size_t i = 0; i < list.size();) {
                const float p = list[i].position;
                std::size_t starts = 0, ends = 0;
                for (; i < list.size() && list[i].position == p; ++i)
                    (list[i].is_end ? ends : starts) += 1;
                above -= ends;
                if (p > lo && p < hi) {
                    const float area_below = 2 * (e1 * e2 + (p - lo) * (e1 + e2));
                    const float area_above = 2 * (e1 * e2 + (hi - p) * (e1 + e2));
                    const float bonus = (below == 0 || above == 0) ? options_.empty_bonus : 0;
                    const float cost = options_.traversal_cost +
                                       options_.intersection_cost * (1 - bonus) * inv_area *
                                           (area_below * float(below) + area_above * float(above));
                    if (cost < best.cost) best = {axis, p, cost};
                }
                below += starts;
            }
        }
        return best;
    }

    void make_leaf(std::uint32_t node_index, const std::vector<Event>& events) {
        std::vector<std::uint32_t> primitives;
        for (const Event& e : events)
            if (!e.is_end) primitives.push_back(global_[e.primitive]);
        std::sort(primitives.begin(), primitives.end());
        const auto count = std::uint32_t(primitives.size());
        references_ += count;
        if (count == 1) {
            nodes_[node_index] = KdNode::leaf(1, primitives[0]);
        } else {
            nodes_[node_index] = KdNode::leaf(count, std::uint32_t(leaf_primitives_.size()));
            leaf_primitives_.insert(leaf_primitives_.end(), primitives.begin(), primitives.end());
        }
    }

    std::span<const Bounds3> boxes_;
    std::span<const std::uint32_t> global_;  // local index -> primitive index
    const KdBuildOptions& options_;
    std::vector<KdNode>& nodes_;
    std::vector<std::uint32_t>& leaf_primitives_;
    std::vector<std::uint8_t> side_;  // per local primitive: 1 below, 2 above, 3 both
    int max_depth_ = 0;
    int deepest_ = 0;
    double reference_budget_ = 0;
    std::size_t references_ = 0;
};

struct StackEntry {
    std::uint32_t node;
    float t_min, t_max;
};

}  // namespace

KdTreeAggregate::KdTreeAggregate(std::span<const Primitive> primitives,
                                 const KdBuildOptions& options)
    : refs_(primitives) {
    assert(refs_.size() < (1u << 30));  // counts and child indices have 30 bits
    std::vector<std::uint32_t> bounded;
    std::vector<Bounds3> boxes;
    for (std::uint32_t i = 0; i < refs_.size(); ++i) {
        const Bounds3 b = refs_.bounds(i);
        if (b.is_finite()) {
            bounded.push_back(i);
            boxes.push_back(b);
            bounds_ = merge(bounds_, b);
        } else {
            unbounded_.push_back(i);
        }
    }
    if (bounded.empty()) return;

    // Grow every box by the classification margin (see the class comment). Positive even for a
    // scene that is one point at the origin, so that every box has extent on every axis.
    const float margin = rounding_margin(bounds_);
    const Vector3 grow{margin, margin, margin};
    for (Bounds3& b : boxes) {
        b = {b.min - grow, b.max + grow};
        tree_bounds_ = merge(tree_bounds_, b);
    }

    Events events;
    for (std::size_t a = 0; a < 3; ++a) {
        events[a].reserve(2 * boxes.size());
        for (std::uint32_t i = 0; i < boxes.size(); ++i) {
            events[a].push_back({boxes[i].min[int(a)], i, false});
            events[a].push_back({boxes[i].max[int(a)], i, true});
        }
        std::sort(events[a].begin(), events[a].end(), [](const Event& x, const Event& y) {
            return x.position < y.position ||
                   (x.position == y.position && x.primitive < y.primitive);
        });
    }
    KdTreeBuilder builder(boxes, bounded, options, nodes_, leaf_primitives_);
    builder.build(tree_bounds_, std::move(events), 0, 0);
    depth_ = builder.deepest();
    nodes_.shrink_to_fit();
    leaf_primitives_.shrink_to_fit();
}

// Front-to-back traversal with t-interval clipping (pbrt-v3, KdTreeAccel::Intersect): at an
// interior node the ray's interval [t_min, t_max] is cut at the plane; the near child gets the
// part before the plane and the far child, pushed, the part after it. A child the interval does
// not reach is skipped. visit_leaf(leaf, interval) returns false to stop.
template <typename VisitLeaf>
void KdTreeAggregate::walk(const Ray& ray, Interval t_range, VisitLeaf&& visit_leaf) const {
    if (nodes_.empty() || !is_finite(ray.origin) || !is_finite(ray.direction)) return;
    const std::optional<Interval> inside = intersect_slabs(tree_bounds_, ray, t_range);
    if (!inside) return;
    const std::array<float, 3> inv{1 / ray.direction.x, 1 / ray.direction.y, 1 / ray.direction.z};
    std::array<StackEntry, kKdMaxDepth> stack;
    int top = 0;
    std::uint32_t index = 0;
    float t_min = inside->min, t_max = inside->max;
    for (;;) {
        const KdNode& node = nodes_[index];
        count_nodes();
        if (!node.is_leaf()) {
            const int axis = node.axis();
            const float origin = ray.origin[axis], d = ray.direction[axis];
            const float split = node.split();
            const std::uint32_t below = index + 1, above = node.above_child();
            const float t_plane = (split - origin) * inv[std::size_t(axis)];
            if (d == 0 || std::isnan(t_plane)) {
                // Parallel to the plane: the ray stays on its origin's side. On the plane itself
                // either side will do, as primitives touching the plane are on both.
                index = origin <= split ? below : above;
                continue;
            }
            const std::uint32_t near = d > 0 ? below : above, far = d > 0 ? above : below;
            if (t_plane <= t_min) {
                index = far;  // crossed the plane before the interval starts
            } else if (t_plane >= t_max) {
                index = near;  // the interval ends before the plane
            } else {
                stack[std::size_t(top++)] = {far, t_plane, t_max};
                index = near;
                t_max = t_plane;
            }
            continue;
        }
        if (!visit_leaf(node, Interval{t_min, t_max})) return;
        if (top == 0) return;
        const StackEntry& next = stack[std::size_t(--top)];
        index = next.node;
        t_min = next.t_min;
        t_max = next.t_max;
    }
}

std::optional<Hit> KdTreeAggregate::closest_hit(const Ray& ray, Interval t_range,
                                                std::uint32_t ray_mask) const {
    std::optional<Hit> closest;
    const auto try_primitive = [&](std::uint32_t index) {
        if (!refs_.visible(index, ray_mask)) return;
        const auto hit = refs_.intersect(index, ray, t_range);
        if (!hit) return;
        const Hit candidate{*hit, refs_[index].primitive};
        if (!closest || nearer(candidate, *closest)) closest = candidate;
        t_range.max = closest->shape_hit.t;  // only nearer hits (or equal ones) from now on
    };
    for (const std::uint32_t index : unbounded_) try_primitive(index);

    Mailbox mailbox;
    walk(ray, t_range, [&](const KdNode& leaf, Interval leaf_t) {
        for (const std::uint32_t index : leaf_primitives(leaf))
            if (mailbox.first_visit(index)) try_primitive(index);
        // The next node's interval starts where this one ends: a hit before that cannot be
        // beaten or tied by primitives only listed farther on (see the class comment).
        return !(closest && closest->shape_hit.t < leaf_t.max);
    });
    return closest;
}

bool KdTreeAggregate::any_hit(const Ray& ray, Interval t_range, std::uint32_t ray_mask) const {
    const auto hits = [&](std::uint32_t index) {
        return refs_.visible(index, ray_mask) && refs_.intersect(index, ray, t_range).has_value();
    };
    for (const std::uint32_t index : unbounded_)
        if (hits(index)) return true;

    bool found = false;
    Mailbox mailbox;
    walk(ray, t_range, [&](const KdNode& leaf, Interval) {
        for (const std::uint32_t index : leaf_primitives(leaf)) {
            if (mailbox.first_visit(index) && hits(index)) {
                found = true;
                return false;
            }
        }
        return true;
    });
    return found;
}

std::size_t KdTreeAggregate::memory_bytes() const {
    return sizeof(*this) + refs_.memory_bytes() + nodes_.capacity() * sizeof(KdNode) +
           (leaf_primitives_.capacity() + unbounded_.capacity()) * sizeof(std::uint32_t);
}

std::size_t KdTreeAggregate::reference_count() const {
    std::size_t n = leaf_primitives_.size();
    for (const KdNode& node : nodes_) n += node.is_leaf() && node.primitive_count() == 1;
    return n;
}

AccelStats KdTreeAggregate::statistics() const {
    AccelStatsTally tally(tree_bounds_);
    // Depth first, each node's box cut from its parent's at the split; depth < kKdMaxDepth.
    const auto walk = [&](const auto& self, std::uint32_t index, const Bounds3& box,
                          int depth) -> void {
        const KdNode& node = nodes_[index];
        if (node.is_leaf()) {
            tally.leaf(box, depth, node.primitive_count());
            return;
        }
        tally.interior(box);
        const int axis = node.axis();
        self(self, index + 1, {box.min, with_component(box.max, axis, node.split())}, depth + 1);
        self(self, node.above_child(), {with_component(box.min, axis, node.split()), box.max},
             depth + 1);
    };
    if (!nodes_.empty()) walk(walk, 0, tree_bounds_, 0);
    return tally.finish(unbounded_.size(), memory_bytes());
}

}  // namespace glint
