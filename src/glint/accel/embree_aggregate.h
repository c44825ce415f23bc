// Intel Embree 3 as an acceleration structure behind glint's Aggregate interface: the reference
// for traversal speed, and an optional back end (--accel embree) in builds with Embree.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "glint/accel/aggregate.h"

namespace glint {

// Meshes and triangles become Embree triangle geometries (Embree's own watertight test); every
// other bounded shape is an Embree user geometry whose callbacks call glint's bounds() and
// intersect(); unbounded shapes (planes) are tested one by one beside the scene, as in
// BvhAggregate. The scene is built with RTC_SCENE_FLAG_ROBUST (watertight triangles, conservative
// boxes) and, by default, RTC_BUILD_QUALITY_HIGH (spatial splits for triangles): render quality
// over build speed. Medium quality (binned SAH alone, as glint's own build) is the reference for
// build times. Visibility masks are Embree's geometry masks.
//
// Differences from the other aggregates, all from Embree's own triangle test:
// - Triangle t values may differ from glint's Moeller-Trumbore in the last bits, and a ray that
//   grazes an edge exactly may hit in one and miss in the other. u, v are still the barycentric
//   weights of vertices 1 and 2 and part the mesh's triangle index, so surface_at() works as is.
// - At exactly equal t, hits between user geometries and the plane list follow nearer() (the lower
//   primitive index); a tie that involves an Embree triangle may resolve either way.
// - Embree traces only in front of the origin: a negative t_range.min counts as 0.
enum class EmbreeBuildQuality { medium, high };

class EmbreeAggregate final : public Aggregate {
public:
    // Throws std::runtime_error when Embree cannot create its device or build the scene (with
    // Embree's message). Builds run on the calling thread's oneTBB arena.
    explicit EmbreeAggregate(std::span<const Primitive> primitives,
                             EmbreeBuildQuality quality = EmbreeBuildQuality::high);
    ~EmbreeAggregate() override;
    EmbreeAggregate(const EmbreeAggregate&) = delete;
    EmbreeAggregate& operator=(const EmbreeAggregate&) = delete;

    Bounds3 bounds() const override { return bounds_; }
    // Embree's own allocations for this scene (counted through its memory monitor), the padded
    // vertex copies, and the index maps.
    std::size_t memory_bytes() const override;
    // Embree 3's API does not expose its BVH's nodes or leaves: only the memory and the unbounded
    // primitives are known (available is false).
    AccelStats statistics() const override;

    // The Embree scene and what its callbacks read; public only so that they can name it.
    struct Scene;

private:
    std::optional<Hit> closest_hit(const Ray& ray, Interval t_range,
                                   std::uint32_t ray_mask) const override;
    bool any_hit(const Ray& ray, Interval t_range, std::uint32_t ray_mask) const override;
    // Packets through Embree's rtcIntersect8 and rtcOccluded8 (coherent rays).
    void closest_hits(std::span<const Ray> rays, Interval t_range, std::uint32_t ray_mask,
                      std::optional<Hit>* hits) const override;
    unsigned any_hits(std::span<const Ray> rays, const Interval* t_ranges,
                      std::uint32_t ray_mask) const override;
    // The unbounded primitives (planes), tested beside Embree's scene: the nearest hit within
    // t_range, whose far end comes to it; whether any blocks the ray.
    std::optional<Hit> closest_unbounded(const Ray& ray, std::uint32_t ray_mask,
                                         Interval& t_range) const;
    bool any_unbounded(const Ray& ray, std::uint32_t ray_mask, Interval t_range) const;

    std::span<const Primitive> primitives_;
    std::unique_ptr<Scene> scene_;
    std::vector<std::uint32_t> unbounded_;  // primitives with infinite bounds
    Bounds3 bounds_;
};

}  // namespace glint
