// Building the uniform grid (resolution, reference budget, CSR cell lists) and its two queries.
#include "glint/accel/grid_aggregate.h"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "glint/accel/mailbox.h"
#include "glint/accel/rounding_margin.h"
#include "glint/geometry/traversal_counters.h"

namespace glint {

namespace {

// Cells never exceed this many in all (a few hundred MB of offsets), whatever the density asks.
constexpr double kMaxCellBudget = double(1 << 26);
constexpr int kMaxCellsPerAxis = 1 << 16;

// The range of cell columns, per axis, that a box grown by `margin` overlaps.
struct CellRange {
    std::array<int, 3> lo, hi;

    std::uint64_t count() const {
        std::uint64_t n = 1;
        for (std::size_t a = 0; a < 3; ++a) n *= std::uint64_t(hi[a] - lo[a] + 1);
        return n;
    }
};

CellRange cell_range(const GridLayout& grid, const Bounds3& b, const std::array<float, 3>& margin) {
    CellRange r;
    for (int axis = 0; axis < 3; ++axis) {
        const auto a = std::size_t(axis);
        r.lo[a] = grid.coordinate(b.min[axis] - margin[a], axis);
        r.hi[a] = grid.coordinate(b.max[axis] + margin[a], axis);
    }
    return r;
}

// Overlap margin per axis (see the class comment): 1/256 of a cell covers the DDA's and the
// shapes' rounding for rays from near the scene; 2^-20 of the largest coordinate (8 ulps) covers
// scenes far from the origin, where a cell may be only a few ulps wide.
std::array<float, 3> overlap_margin(const GridLayout& grid) {
    const float absolute = magnitude(grid.bounds) * 0x1p-20f;
    return {grid.cell_size[0] / 256 + absolute, grid.cell_size[1] / 256 + absolute,
            grid.cell_size[2] / 256 + absolute};
}

}  // namespace

GridLayout GridLayout::of(const Bounds3& bounds, std::array<int, 3> resolution) {
    GridLayout g;
    g.bounds = bounds;
    g.resolution = resolution;
    for (int axis = 0; axis < 3; ++axis) {
        const auto a = std::size_t(axis);
        g.cell_size[a] = (bounds.max[axis] - bounds.min[axis]) / float(resolution[a]);
        g.inv_cell_size[a] = 1 / g.cell_size[a];
    }
    return g;
}

std::array<int, 3> grid_resolution(Vector3 extent, std::size_t primitive_count, float density) {
    const double budget =
        std::clamp(double(density) * double(primitive_count), 1.0, kMaxCellBudget);
    std::array<int, 3> resolution{1, 1, 1};
    std::array<bool, 3> active{};
    for (int a = 0; a < 3; ++a) active[std::size_t(a)] = extent[a] > 0 && std::isfinite(extent[a]);
    // Each round spreads the budget over the active axes; an axis whose share is under one cell
    // drops out with one cell, and the others share the budget again. Logarithms keep a tiny
    // volume from overflowing the cells per unit length.
    for (int round = 0; round < 3; ++round) {
        int k = 0;
        double log_volume = 0;
        for (int a = 0; a < 3; ++a) {
            if (!active[std::size_t(a)]) continue;
            ++k;
            log_volume += std::log(double(extent[a]));
        }
        if (k == 0) break;
        const double log_cells_per_unit = (std::log(budget) - log_volume) / k;
        bool dropped = false;
        for (int a = 0; a < 3; ++a) {
            if (!active[std::size_t(a)]) continue;
            if (std::log(double(extent[a])) + log_cells_per_unit < 0) {  // under one cell
                active[std::size_t(a)] = false;
                dropped = true;
            }
        }
        if (dropped) continue;
        for (int a = 0; a < 3; ++a) {
            if (!active[std::size_t(a)]) continue;
            const double cells = std::exp(std::log(double(extent[a])) + log_cells_per_unit);
            resolution[std::size_t(a)] =
                int(std::clamp(std::round(cells), 1.0, double(kMaxCellsPerAxis)));
        }
        break;
    }
    return resolution;
}

GridAggregate::GridAggregate(std::span<const Primitive> primitives, const GridBuildOptions& options)
    : refs_(primitives) {
    assert(refs_.size() < Mailbox::kEmpty);
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

    // Pad the cells' box so that no axis is flat (a scene in a plane still has one cell of
    // positive thickness) and hits on the scene's boundary lie strictly inside.
    const float pad = rounding_margin(bounds_);
    const Vector3 padding{pad, pad, pad};
    const Bounds3 cell_bounds{bounds_.min - padding, bounds_.max + padding};

    // Coarsen until the references fit the budget; each round costs O(N).
    const double max_references =
        std::min(double(options.max_references_per_primitive) * double(bounded.size()) + 4096,
                 double(Mailbox::kEmpty));
    double density = options.density;
    std::uint64_t references = 0;
    for (;;) {
        layout_ = GridLayout::of(cell_bounds,
                                 grid_resolution(cell_bounds.diagonal(), bounded.size(), density));
        const std::array<float, 3> margin = overlap_margin(layout_);
        references = 0;
        for (const Bounds3& b : boxes) references += cell_range(layout_, b, margin).count();
        if (double(references) <= max_references || layout_.cell_count() == 1) break;
        density *= std::clamp(max_references / double(references), 1.0 / 64, 0.7);
    }

    // Compressed sparse rows: count, prefix-sum, fill. Filling in primitive order leaves each
    // cell's list in increasing index.
    const std::array<float, 3> margin = overlap_margin(layout_);
    cell_offsets_.assign(layout_.cell_count() + 1, 0);
    const auto for_each_cell = [&](const Bounds3& b, auto&& f) {
        const CellRange r = cell_range(layout_, b, margin);
        for (int z = r.lo[2]; z <= r.hi[2]; ++z)
            for (int y = r.lo[1]; y <= r.hi[1]; ++y)
                for (int x = r.lo[0]; x <= r.hi[0]; ++x) f(layout_.cell_index({x, y, z}));
    };
    for (const Bounds3& b : boxes)
        for_each_cell(b, [&](std::uint32_t c) { ++cell_offsets_[c + 1]; });
    for (std::size_t c = 1; c < cell_offsets_.size(); ++c) cell_offsets_[c] += cell_offsets_[c - 1];
    cell_primitives_.resize(references);
    std::vector<std::uint32_t> fill(cell_offsets_.begin(), cell_offsets_.end() - 1);
    for (std::size_t i = 0; i < boxes.size(); ++i)
        for_each_cell(boxes[i], [&](std::uint32_t c) { cell_primitives_[fill[c]++] = bounded[i]; });
}

std::optional<Hit> GridAggregate::closest_hit(const Ray& ray, Interval t_range,
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
    if (cell_offsets_.empty()) return closest;

    Mailbox mailbox;
    walk_grid(layout_, ray, t_range, [&](std::uint32_t cell, Interval cell_t) {
        count_nodes();
        for (std::uint32_t i = cell_offsets_[cell]; i < cell_offsets_[cell + 1]; ++i) {
            const std::uint32_t index = cell_primitives_[i];
            if (mailbox.first_visit(index)) try_primitive(index);
        }
        // A hit within this cell cannot be beaten by a primitive of a later cell (see the class
        // comment); one beyond it can.
        return !(closest && closest->shape_hit.t <= cell_t.max);
    });
    return closest;
}

bool GridAggregate::any_hit(const Ray& ray, Interval t_range, std::uint32_t ray_mask) const {
    const auto hits = [&](std::uint32_t index) {
        return refs_.visible(index, ray_mask) && refs_.intersect(index, ray, t_range).has_value();
    };
    for (const std::uint32_t index : unbounded_)
        if (hits(index)) return true;
    if (cell_offsets_.empty()) return false;

    bool found = false;
    Mailbox mailbox;
    walk_grid(layout_, ray, t_range, [&](std::uint32_t cell, Interval) {
        count_nodes();
        for (std::uint32_t i = cell_offsets_[cell]; i < cell_offsets_[cell + 1]; ++i) {
            const std::uint32_t index = cell_primitives_[i];
            if (mailbox.first_visit(index) && hits(index)) {
                found = true;
                return false;
            }
        }
        return true;
    });
    return found;
}

std::size_t GridAggregate::memory_bytes() const {
    return sizeof(*this) + refs_.memory_bytes() +
           (cell_offsets_.capacity() + cell_primitives_.capacity() + unbounded_.capacity()) *
               sizeof(std::uint32_t);
}

AccelStats GridAggregate::statistics() const {
    AccelStatsTally tally(layout_.bounds);
    if (!cell_offsets_.empty()) {
        const std::array<int, 3>& n = layout_.resolution;
        for (int z = 0; z < n[2]; ++z) {
            for (int y = 0; y < n[1]; ++y) {
                for (int x = 0; x < n[0]; ++x) {
                    const Point3 lo{layout_.boundary(x, 0), layout_.boundary(y, 1),
                                    layout_.boundary(z, 2)};
                    const Point3 hi{layout_.boundary(x + 1, 0), layout_.boundary(y + 1, 1),
                                    layout_.boundary(z + 1, 2)};
                    tally.cell({lo, hi}, cell_primitives(layout_.cell_index({x, y, z})).size());
                }
            }
        }
    }
    return tally.finish(unbounded_.size(), memory_bytes());
}

}  // namespace glint
