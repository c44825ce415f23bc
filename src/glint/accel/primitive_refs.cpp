// Numbering the triangles of meshes placed directly beside whole primitives, for the grid,
// the kd-tree and the list.
#include "glint/accel/primitive_refs.h"

#include "glint/geometry/traversal_counters.h"

namespace glint {

std::size_t reference_count(const Shape& shape) {
    const auto* mesh = std::get_if<TriangleMesh>(&shape);
    return mesh ? mesh->data->triangles.size() : 1;
}

PrimitiveRefs::PrimitiveRefs(std::span<const Primitive> primitives) : primitives_(primitives) {
    std::size_t count = 0;
    for (const Primitive& p : primitives) count += reference_count(p.shape);
    refs_.reserve(count);
    for (std::uint32_t i = 0; i < primitives.size(); ++i) {
        const auto* mesh = std::get_if<TriangleMesh>(&primitives[i].shape);
        if (!mesh) {
            refs_.push_back({i, kWholePrimitive});
            continue;
        }
        const auto triangles = std::uint32_t(mesh->data->triangles.size());
        for (std::uint32_t t = 0; t < triangles; ++t) refs_.push_back({i, t});
    }
}

Bounds3 PrimitiveRefs::bounds(std::uint32_t i) const {
    const PrimitiveRef r = refs_[i];
    const Shape& shape = primitives_[r.primitive].shape;
    if (r.triangle == kWholePrimitive) return glint::bounds(shape);
    const MeshData& mesh = *std::get<TriangleMesh>(shape).data;
    const auto& corners = mesh.triangles[r.triangle];
    Bounds3 b;
    for (const std::uint32_t v : corners) b = merge(b, mesh.positions[v]);
    return b;
}

std::optional<ShapeHit> PrimitiveRefs::intersect(std::uint32_t i, const Ray& ray,
                                                 Interval t_range) const {
    const PrimitiveRef r = refs_[i];
    const Shape& shape = primitives_[r.primitive].shape;
    if (r.triangle == kWholePrimitive) return glint::intersect(shape, ray, t_range);
    count_primitives();
    return intersect_triangle(*std::get<TriangleMesh>(shape).data, r.triangle, ray, t_range);
}

}  // namespace glint
