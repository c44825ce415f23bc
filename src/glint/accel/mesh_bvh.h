// Each mesh's own BVH, the lower level of the two-level structure: a mesh traced whole (placed
// by a transform or an instance, moving, a CSG operand, or listed by a light buffer) is traced
// through a wide BVH over its triangles, built once when the world is made and shared by every
// placement; the scene's structure above holds the placements. A mesh placed in the scene as it
// is needs none: the scene's structure takes its triangles one by one.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <span>

#include "glint/accel/primitive.h"
#include "glint/accel/wide_bvh.h"
#include "glint/geometry/triangle_mesh.h"

namespace glint {

class MeshBvh final : public MeshAccelerator {
public:
    // Builds the tree over the mesh's triangles, in blocks of four whose lanes name triangle
    // indices: in parallel, the same tree for any number of threads.
    explicit MeshBvh(std::shared_ptr<const MeshData> mesh);

    // The watertight test on the triangles of the leaves the ray enters, four at a time: the
    // answers of TriangleMesh's triangle-by-triangle test, the lower triangle at equal t.
    std::optional<ShapeHit> intersect(const Ray& ray, Interval t_range) const override;
    bool occluded(const Ray& ray, Interval t_range) const override;
    // Up to kRayPacketSize rays traced together (wide_bvh_packet.h): hits[i], and bit i of
    // occluded_packet's result, as intersect() and occluded() answer for rays[i] alone.
    void intersect_packet(std::span<const Ray> rays, const Interval* t_ranges,
                          std::optional<ShapeHit>* hits) const;
    unsigned occluded_packet(std::span<const Ray> rays, const Interval* t_ranges) const;

    const WideBvh& tree() const { return bvh_; }

private:
    std::shared_ptr<const MeshData> mesh_;
    WideBvh bvh_;
};

// What bind_mesh_bvhs built.
struct MeshBvhBinding {
    std::size_t meshes = 0;        // distinct meshes given a BVH
    std::size_t memory_bytes = 0;  // of their BVHs
};

// Gives every mesh that the primitives trace whole a MeshBvh, one per distinct mesh (built side
// by side): the meshes inside transforms, moving shapes and CSG operands, and the top-level
// meshes for which whole_at_top holds (the scene's structure splits the others into triangles).
// Shapes around a bound mesh are copied with the bound mesh in them; a shape shared by several
// others (an instanced object) stays one shared copy.
MeshBvhBinding bind_mesh_bvhs(std::span<Primitive> primitives,
                              const std::function<bool(const Shape&)>& whole_at_top);

}  // namespace glint
