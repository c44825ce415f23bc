// The scene-level bounding volume hierarchy: one wide BVH over the bounded primitives and the
// single triangles of meshes placed directly, and the unbounded primitives (planes) tested one by
// one beside it. Triangles and spheres sit in leaves of blocks of four, each block tested in one
// SIMD pass; every other shape in leaves of its own.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "glint/accel/aggregate.h"
#include "glint/accel/wide_bvh_traversal.h"

namespace glint {

class BvhAggregate final : public Aggregate {
public:
    // At most 2^29 - 1 primitives and triangles in all (std::length_error otherwise).
    explicit BvhAggregate(std::span<const Primitive> primitives);

    Bounds3 bounds() const override { return bounds_; }
    std::size_t memory_bytes() const override;
    AccelStats statistics() const override;

private:
    std::optional<Hit> closest_hit(const Ray& ray, Interval t_range,
                                   std::uint32_t ray_mask) const override;
    bool any_hit(const Ray& ray, Interval t_range, std::uint32_t ray_mask) const override;
    // A packet through the wide BVH (wide_bvh_packet.h), each ray's leaves tested as alone.
    void closest_hits(std::span<const Ray> rays, Interval t_range, std::uint32_t ray_mask,
                      std::optional<Hit>* hits) const override;
    unsigned any_hits(std::span<const Ray> rays, const Interval* t_ranges,
                      std::uint32_t ray_mask) const override;

    struct NearestHit;  // the closest hit so far of one ray
    // One ray against the unbounded primitives, or a leaf's, that ray_mask sees: keeps the
    // nearest in `nearest` and brings range.max to it. triangles() and spheres() give the ray's
    // block testers.
    void closest_in_unbounded(const Ray& ray, std::uint32_t ray_mask, NearestHit& nearest,
                              Interval& range) const;
    // Whether the unbounded primitives, or a leaf's, block the ray within range.
    bool any_in_unbounded(const Ray& ray, Interval range, std::uint32_t ray_mask) const;
    template <bool kSimd, class Triangles, class Spheres>
    bool any_in_leaf(const Ray& ray, std::uint32_t leaf, std::uint32_t count,
                     std::uint32_t ray_mask, Triangles&& triangles, Spheres&& spheres,
                     Interval range) const;
    template <bool kSimd, class Triangles, class Spheres>
    void closest_in_leaf(const Ray& ray, std::uint32_t leaf, std::uint32_t count,
                         std::uint32_t ray_mask, Triangles&& triangles, Spheres&& spheres,
                         NearestHit& nearest, Interval& range) const;

    // A reference numbers every triangle of a mesh primitive and every other primitive, in
    // primitive order: the lanes of the tree's blocks name references.
    struct Reference {
        std::uint32_t primitive;
        std::uint32_t triangle;  // of a mesh; 0 for a lone Triangle
    };
    Reference reference(std::uint32_t ref) const;
    bool visible(std::uint32_t primitive, std::uint32_t ray_mask) const {
        return (primitives_[primitive].visibility & ray_mask) != 0;
    }
    // Block tests' accept(lane): whether the lane's primitive is seen by rays of ray_mask. Asked
    // only of lanes a ray hits, and answered at once when every primitive is seen alike.
    auto triangle_lane_visible(const TriangleBlock& block, std::uint32_t ray_mask) const {
        return [this, &block, ray_mask](int lane) {
            return common_visibility_ || visible(reference(block.id[lane]).primitive, ray_mask);
        };
    }
    auto sphere_lane_visible(const SphereBlock& block, std::uint32_t ray_mask) const {
        return [this, &block, ray_mask](int lane) {
            return common_visibility_ || visible(block.id[lane], ray_mask);
        };
    }

    std::span<const Primitive> primitives_;
    // Leaves of blocks (lanes: references) and of whole primitives (primitive indices).
    WideBvh bvh_;
    std::vector<std::uint32_t> first_reference_;  // of each primitive, and the total at the end
    // No meshes of other than one triangle: a reference is its primitive, found without a search.
    bool one_reference_each_ = true;
    std::vector<std::uint32_t> unbounded_;  // primitives with infinite bounds
    Bounds3 bounds_;                        // of the bounded primitives, not grown
    // The visibility every primitive has, when they all have the same: lanes need no check.
    std::optional<std::uint32_t> common_visibility_;
};

}  // namespace glint
