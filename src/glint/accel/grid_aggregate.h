// The uniform grid: cells over the bounded primitives, each listing the primitives that overlap
// it, walked cell by cell along the ray with a 3D-DDA (Amanatides and Woo 1987).
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "glint/accel/aggregate.h"
#include "glint/accel/primitive_refs.h"

namespace glint {

// Where the cells are: `resolution` cells per axis splitting `bounds` evenly. Cell (x, y, z) has
// index (z * ny + y) * nx + x.
struct GridLayout {
    Bounds3 bounds;
    std::array<int, 3> resolution{1, 1, 1};
    std::array<float, 3> cell_size{1, 1, 1};
    std::array<float, 3> inv_cell_size{1, 1, 1};

    // Bounds must be non-empty with a positive finite extent on every axis; resolution >= 1.
    static GridLayout of(const Bounds3& bounds, std::array<int, 3> resolution);

    std::size_t cell_count() const {
        return std::size_t(resolution[0]) * std::size_t(resolution[1]) * std::size_t(resolution[2]);
    }
    std::uint32_t cell_index(std::array<int, 3> cell) const {
        return std::uint32_t((cell[2] * resolution[1] + cell[1]) * resolution[0] + cell[0]);
    }
    // The cell column holding coordinate x on the axis, clamped into the grid (NaN gives 0).
    // The float is compared before the cast, which would be undefined out of range.
    int coordinate(float x, int axis) const {
        const float f = (x - bounds.min[axis]) * inv_cell_size[std::size_t(axis)];
        if (!(f > 0)) return 0;
        const int last = resolution[std::size_t(axis)] - 1;
        return f < float(last) ? int(f) : last;
    }
    // The plane between cell columns k - 1 and k on the axis.
    float boundary(int k, int axis) const {
        return bounds.min[axis] + float(k) * cell_size[std::size_t(axis)];
    }
};

// Cells per axis for primitives filling a box of this extent: about `density` cells per
// primitive in all, cubical where possible, so cells per axis = extent * cbrt(density N / V).
// O(N) cells is what Ize, Shirley and Parker (2007, "Grid Creation Strategies for Efficient Ray
// Tracing") find fastest for well-behaved models (long thin primitives want more). An axis that
// would get less than one cell (a flat or thin scene) gets exactly one, and its share of the
// budget goes to the other axes: a scene in a plane becomes a 2D grid, not a sliver of cells.
// Extents must be positive; the product stays within a small factor of max(1, density N).
std::array<int, 3> grid_resolution(Vector3 extent, std::size_t primitive_count, float density);

// The cells the ray passes through with t in t_range, front to back (Amanatides and Woo 1987,
// "A Fast Voxel Traversal Algorithm for Ray Tracing"). visit(cell_index, cell_t) gets the cell
// and the t interval the ray spends in it, and returns false to stop the walk. The crossing
// with the next cell plane is recomputed from the origin at each step rather than accumulated
// (t += delta), so rounding does not grow with the number of cells walked. Rays with a NaN or
// infinite origin or direction visit nothing. A zero direction component never steps along its
// axis; a zero direction visits the origin's cell only. Terminates after at most nx + ny + nz
// steps whatever the input: each step moves one axis monotonically towards its end.
template <typename Visit>
void walk_grid(const GridLayout& grid, const Ray& ray, Interval t_range, Visit&& visit) {
    if (!is_finite(ray.origin) || !is_finite(ray.direction)) return;
    const std::optional<Interval> inside = intersect_slabs(grid.bounds, ray, t_range);
    if (!inside || !std::isfinite(inside->min)) return;
    const float t_end = inside->max;
    float t = inside->min;
    const Point3 entry = ray.at(t);

    std::array<int, 3> cell, step, stop;
    std::array<float, 3> inv, next;
    const auto crossing = [&](int axis) {
        const auto a = std::size_t(axis);
        if (step[a] == 0) return kInfinity;
        const int k = step[a] > 0 ? cell[a] + 1 : cell[a];
        return (grid.boundary(k, axis) - ray.origin[axis]) * inv[a];
    };
    for (int axis = 0; axis < 3; ++axis) {
        const auto a = std::size_t(axis);
        const float d = ray.direction[axis];
        cell[a] = grid.coordinate(entry[axis], axis);
        inv[a] = 1 / d;
        step[a] = d > 0 ? 1 : d < 0 ? -1 : 0;
        stop[a] = d > 0 ? grid.resolution[a] : -1;
        next[a] = crossing(axis);
    }
    for (;;) {
        int axis = next[0] < next[1] ? 0 : 1;
        if (next[2] < next[std::size_t(axis)]) axis = 2;
        const auto a = std::size_t(axis);
        const float t_exit = next[a] < t_end ? next[a] : t_end;
        if (!visit(grid.cell_index(cell), Interval{t, t_exit})) return;
        // Also stops for an infinite crossing (axis never stepped): the ray ends in this cell.
        if (!(next[a] < t_end)) return;
        cell[a] += step[a];
        if (cell[a] == stop[a]) return;
        t = next[a];
        next[a] = crossing(axis);
    }
}

struct GridBuildOptions {
    float density = 4;  // cells per bounded primitive, before the reference budget below
    // References (cell, primitive pairs) allowed per bounded primitive, plus a constant: a
    // coarser grid is taken until they fit, so memory stays O(N) even when primitives are
    // large or coincident.
    float max_references_per_primitive = 16;
};

// The grid aggregate. Cells list primitives in a compact (CSR) layout: cell c's primitives are
// cell_primitives_[cell_offsets_[c], cell_offsets_[c + 1]), in increasing index.
//
// Correctness of the early exit: a primitive is listed in every cell its bounds overlap, the
// bounds grown by 1/256 of a cell (and a few ulps of the scene's coordinates). A primitive not
// yet tested therefore has its hits farther along the ray than the cells walked so far plus that
// margin, which covers the rounding of the DDA's crossings and of the shapes' t. So the walk may
// stop as soon as the nearest hit so far lies within the current cell (t <= the cell's exit);
// a hit beyond the cell can still be beaten by a primitive in a later cell.
//
// Where grids fail: one cell per region of space, whatever lies in it. A dense object in a
// large empty scene (the "teapot in a stadium") lands in a few cells with thousands of
// primitives each, and every ray through them tests them all; a million coincident primitives
// make one cell that is as slow as the brute-force list. Results stay exact; use the BVH or
// the kd-tree for such scenes.
class GridAggregate final : public Aggregate {
public:
    explicit GridAggregate(std::span<const Primitive> primitives,
                           const GridBuildOptions& options = {});

    Bounds3 bounds() const override { return bounds_; }
    std::size_t memory_bytes() const override;
    AccelStats statistics() const override;

    const GridLayout& layout() const { return layout_; }
    // The primitives listed in a cell, in increasing index.
    std::span<const std::uint32_t> cell_primitives(std::uint32_t cell) const {
        return std::span(cell_primitives_)
            .subspan(cell_offsets_[cell], cell_offsets_[cell + 1] - cell_offsets_[cell]);
    }
    // Cell-primitive pairs in all (each bounded primitive counts once per cell it overlaps).
    std::size_t reference_count() const { return cell_primitives_.size(); }

private:
    std::optional<Hit> closest_hit(const Ray& ray, Interval t_range,
                                   std::uint32_t ray_mask) const override;
    bool any_hit(const Ray& ray, Interval t_range, std::uint32_t ray_mask) const override;

    PrimitiveRefs refs_;  // what the cells or leaves list, by index
    Bounds3 bounds_;      // of the bounded primitives, as given (the layout's are padded)
    GridLayout layout_;
    std::vector<std::uint32_t> cell_offsets_;     // cell_count() + 1 entries; empty: no cells
    std::vector<std::uint32_t> cell_primitives_;  // reference indices (refs_), cell by cell
    std::vector<std::uint32_t> unbounded_;        // primitives with infinite bounds (planes)
};

}  // namespace glint
