// The scene-level bounding volume hierarchy: a BVH over the bounded primitives, and the
// unbounded ones (planes) tested one by one beside it.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "glint/accel/aggregate.h"
#include "glint/accel/primitive_refs.h"
#include "glint/geometry/bvh4_traversal.h"

namespace glint {

class BvhAggregate final : public Aggregate {
public:
    explicit BvhAggregate(std::span<const Primitive> primitives);

    Bounds3 bounds() const override { return bounds_; }
    std::size_t memory_bytes() const override;

private:
    std::optional<Hit> closest_hit(const Ray& ray, Interval t_range,
                                   std::uint32_t ray_mask) const override;
    bool any_hit(const Ray& ray, Interval t_range, std::uint32_t ray_mask) const override;

    PrimitiveRefs refs_;  // primitives, and the triangles of meshes placed directly
    Bvh4 bvh_;            // over the bounded references; its leaves hold reference indices
    std::vector<std::uint32_t> unbounded_;  // primitives with infinite bounds
    Bounds3 bounds_;                        // of the bounded primitives, not grown
};

}  // namespace glint
