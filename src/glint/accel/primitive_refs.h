// What acceleration structures sort: whole primitives, and the single triangles of meshes placed
// directly in the scene, so that triangles and analytic shapes share one structure.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "glint/accel/primitive.h"

namespace glint {

// Not a triangle: the whole primitive.
inline constexpr std::uint32_t kWholePrimitive = 0xffffffffu;

struct PrimitiveRef {
    std::uint32_t primitive;  // index into the scene's primitives
    std::uint32_t triangle;   // the mesh's triangle, or kWholePrimitive
};

// A TriangleMesh primitive becomes one reference per triangle; every other primitive (including
// an instance, a Transformed mesh, which keeps its mesh's own BVH: the bottom level of a
// two-level structure) one reference. References run in primitive order and, within a mesh, in
// triangle order, so "the lower reference" is "the lower primitive, then the lower triangle":
// nearer()'s order at equal t.
// The references a shape becomes: its triangles for a TriangleMesh, else one.
std::size_t reference_count(const Shape& shape);

class PrimitiveRefs {
public:
    explicit PrimitiveRefs(std::span<const Primitive> primitives);

    std::size_t size() const { return refs_.size(); }
    std::span<const Primitive> primitives() const { return primitives_; }
    const PrimitiveRef& operator[](std::uint32_t i) const { return refs_[i]; }

    Bounds3 bounds(std::uint32_t i) const;
    // Whether reference i is seen by rays with this mask.
    bool visible(std::uint32_t i, std::uint32_t ray_mask) const {
        return (primitives_[refs_[i].primitive].visibility & ray_mask) != 0;
    }
    // The hit on reference i within t_range, as the primitive's own intersect() would report it
    // (a triangle's part is its index in the mesh). The mask is not checked here.
    std::optional<ShapeHit> intersect(std::uint32_t i, const Ray& ray, Interval t_range) const;

    std::size_t memory_bytes() const { return refs_.capacity() * sizeof(PrimitiveRef); }

private:
    std::span<const Primitive> primitives_;
    std::vector<PrimitiveRef> refs_;
};

}  // namespace glint
