// Building the light buffer's direction cube and answering shadow feelers from its cells.
#include "glint/accel/light_buffer.h"

#include <algorithm>
#include <cmath>

namespace glint {

namespace {

// Face f = 2 * axis + (1 for the negative side) of the cube around the light; a direction d
// belongs to the face of its dominant axis, at (u, v) = (d[a1], d[a2]) / |d[axis]| in [-1, 1].
struct Face {
    int axis, a1, a2;
    float sign;
};

Face face(int f) {
    const int axis = f / 2;
    return {axis, (axis + 1) % 3, (axis + 2) % 3, f % 2 == 0 ? 1.0f : -1.0f};
}

int cell_index(float c, int resolution) {
    const int i = static_cast<int>(std::floor((c + 1) * 0.5f * float(resolution)));
    return std::clamp(i, 0, resolution - 1);
}

// The cells of face f that directions towards the box (relative to the light) can fall in, as
// [u0, u1] x [v0, v1]; false when no direction towards the box belongs to the face. The box is
// cut to the half-space in front of the face; the extreme ratios of a box lie at its corners.
bool face_cells(const Bounds3& box, int f, int resolution, int& u0, int& u1, int& v0, int& v1) {
    const Face fc = face(f);
    float near = fc.sign > 0 ? box.min[fc.axis] : -box.max[fc.axis];
    const float far = fc.sign > 0 ? box.max[fc.axis] : -box.min[fc.axis];
    if (far <= 0) return false;
    // Directions at a depth near 0 have unbounded ratios: clamping them to the face's edge
    // keeps the result conservative.
    near = std::max(near, far * 1e-6f);
    float umin = kInfinity, umax = -kInfinity, vmin = kInfinity, vmax = -kInfinity;
    for (const float depth : {near, far})
        for (const float a : {box.min[fc.a1], box.max[fc.a1]})
            for (const float b : {box.min[fc.a2], box.max[fc.a2]}) {
                umin = std::min(umin, a / depth), umax = std::max(umax, a / depth);
                vmin = std::min(vmin, b / depth), vmax = std::max(vmax, b / depth);
            }
    // A margin covers the rounding of the ratios: a feeler's direction, computed from another
    // point, may round across a cell boundary that the box's corners just reach.
    constexpr float kMargin = 1e-5f;
    umin -= kMargin, vmin -= kMargin, umax += kMargin, vmax += kMargin;
    if (umin > 1 || umax < -1 || vmin > 1 || vmax < -1) return false;
    u0 = cell_index(std::max(umin, -1.0f), resolution);
    u1 = cell_index(std::min(umax, 1.0f), resolution);
    v0 = cell_index(std::max(vmin, -1.0f), resolution);
    v1 = cell_index(std::min(vmax, 1.0f), resolution);
    return true;
}

Bounds3 relative(const Bounds3& b, Point3 origin) {
    return {to_point(b.min - origin), to_point(b.max - origin)};
}

}  // namespace

bool LightBuffer::tests_whole(const Shape& shape) {
    const auto* mesh = std::get_if<TriangleMesh>(&shape);
    return !mesh || mesh->data->triangles.size() <= kMaxListTested;
}

LightBuffer::LightBuffer(Point3 light, std::span<const Primitive> primitives, int resolution)
    : light_(light), primitives_(primitives) {
    // About one primitive a cell on average, between 8 and 256 cells along an edge.
    resolution_ = resolution > 0
                      ? resolution
                      : std::clamp(int(std::sqrt(double(primitives.size()) / 6)), 8, 256);
    const std::size_t cells = 6 * std::size_t(resolution_) * resolution_;
    std::vector<std::uint32_t> count(cells + 1, 0);

    // Two passes over the primitives' cells: count, then fill (a compact CSR layout).
    const auto for_each_cell = [&](std::uint32_t index, auto&& visit) {
        const Bounds3 box = relative(glint::bounds(primitives[index].shape), light);
        if (box.contains({0, 0, 0})) {
            // The light is inside the primitive's bounds: it may block any direction.
            for (std::size_t c = 0; c < cells; ++c) visit(c);
            return;
        }
        for (int f = 0; f < 6; ++f) {
            int u0, u1, v0, v1;
            if (!face_cells(box, f, resolution_, u0, u1, v0, v1)) continue;
            for (int v = v0; v <= v1; ++v)
                for (int u = u0; u <= u1; ++u)
                    visit((std::size_t(f) * resolution_ + v) * resolution_ + u);
        }
    };
    std::vector<std::uint32_t> bounded;
    crowded_.assign(cells, false);
    for (std::uint32_t i = 0; i < primitives.size(); ++i) {
        if ((primitives[i].visibility & kVisibleToShadowRays) == 0) continue;
        if (!glint::bounds(primitives[i].shape).is_finite()) {
            unbounded_.push_back(i);
            continue;
        }
        if (!tests_whole(primitives[i].shape)) {
            for_each_cell(i, [&](std::size_t c) { crowded_[c] = true; });
            continue;
        }
        bounded.push_back(i);
        for_each_cell(i, [&](std::size_t c) { ++count[c + 1]; });
    }
    for (std::size_t c = 0; c < cells; ++c) count[c + 1] += count[c];
    cell_start_ = count;
    entries_.resize(count[cells]);
    for (const std::uint32_t i : bounded)
        for_each_cell(i, [&](std::size_t c) { entries_[count[c]++] = i; });
}

std::uint32_t LightBuffer::cell_of(Vector3 d) const {
    const Vector3 a = abs(d);
    const int axis = a.x >= a.y && a.x >= a.z ? 0 : a.y >= a.z ? 1 : 2;
    const int f = 2 * axis + (d[axis] < 0 ? 1 : 0);
    const Face fc = face(f);
    const float depth = a[axis];
    const int u = cell_index(d[fc.a1] / depth, resolution_);
    const int v = cell_index(d[fc.a2] / depth, resolution_);
    return std::uint32_t((f * resolution_ + v) * resolution_ + u);
}

std::span<const std::uint32_t> LightBuffer::candidates(Vector3 from_light) const {
    const std::uint32_t c = cell_of(from_light);
    return {entries_.data() + cell_start_[c], entries_.data() + cell_start_[c + 1]};
}

std::optional<bool> LightBuffer::occluded(const Ray& ray, Interval t_range,
                                          std::uint32_t& hint) const {
    const auto blocks = [&](std::uint32_t index) {
        return glint::intersect(primitives_[index].shape, ray, t_range).has_value();
    };
    if (hint != kNoPrimitive && blocks(hint)) return true;
    for (const std::uint32_t index : unbounded_) {
        if (index != hint && blocks(index)) return hint = index, true;
    }
    // The feeler runs from the surface point to the light: its cell is that of the point seen
    // from the light.
    const Vector3 from_light = ray.origin - light_;
    if (!(length_squared(from_light) > 0)) return std::nullopt;
    const std::uint32_t cell = cell_of(from_light);
    if (crowded_[cell]) return std::nullopt;
    const std::span<const std::uint32_t> list(entries_.data() + cell_start_[cell],
                                              entries_.data() + cell_start_[cell + 1]);
    if (list.size() > kMaxListTested) return std::nullopt;
    for (const std::uint32_t index : list) {
        if (index != hint && blocks(index)) return hint = index, true;
    }
    return false;
}

std::size_t LightBuffer::memory_bytes() const {
    return sizeof(*this) +
           (cell_start_.capacity() + entries_.capacity() + unbounded_.capacity()) *
               sizeof(std::uint32_t) +
           crowded_.capacity() / 8;
}

}  // namespace glint
