// The one interface every acceleration structure implements: closest hit and any hit over a
// set of primitives. Queries never allocate and never throw.
#pragma once

#include <array>
#include <cassert>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

#include "glint/accel/accel_stats.h"
#include "glint/accel/primitive.h"
#include "glint/geometry/surface_point.h"
#include "glint/math/bounds.h"
#include "glint/math/interval.h"
#include "glint/math/ray.h"

namespace glint {

struct Hit {
    ShapeHit shape_hit;
    std::uint32_t primitive;  // index into the primitives the aggregate was built over
};

// The order of closest hits that every aggregate follows, so that all return exactly the same
// hit: the smaller t; at equal t the lower primitive index, then (two triangles of one mesh) the
// lower part.
constexpr bool nearer(const Hit& a, const Hit& b) {
    if (a.shape_hit.t != b.shape_hit.t) return a.shape_hit.t < b.shape_hit.t;
    if (a.primitive != b.primitive) return a.primitive < b.primitive;
    return a.shape_hit.part < b.shape_hit.part;
}

// Whether a ray can hit anything: a NaN or infinite origin or direction hits nothing, in every
// aggregate alike (slab and shape tests would each treat the NaN their own way).
inline bool is_traceable(const Ray& ray) {
    // x - x is 0 for a finite x and NaN for an infinite or NaN one, and a NaN anywhere makes the
    // sum NaN: one test, where six would each take a branch on every ray.
    const Vector3 o = ray.origin - ray.origin, d = ray.direction - ray.direction;
    return o.x + o.y + o.z + d.x + d.y + d.z == 0;
}

// Some of a packet's rays, gathered in order with their ranges, and the slot in the packet each
// came from: what a structure traces on when the others have left the packet (rays that cannot
// hit anything, or that a plane already blocks).
struct PacketSubset {
    std::array<Ray, kRayPacketSize> rays;
    std::array<Interval, kRayPacketSize> ranges;
    std::array<std::size_t, kRayPacketSize> slot;
    std::size_t size = 0;

    void add(std::size_t i, const Ray& ray, Interval range) {
        rays[size] = ray;
        ranges[size] = range;
        slot[size++] = i;
    }
    std::span<const Ray> rays_span() const { return {rays.data(), size}; }
    // Bit k (ray k of the subset) as bit slot[k] of the packet.
    unsigned in_packet(unsigned bits) const {
        unsigned out = 0;
        for (std::size_t k = 0; k < size; ++k)
            if (bits >> k & 1) out |= 1u << slot[k];
        return out;
    }
};

// Built over a primitive array that the caller keeps alive and unchanged.
class Aggregate {
public:
    virtual ~Aggregate() = default;

    // Bounds of the bounded primitives; unbounded ones (planes) are not included.
    virtual Bounds3 bounds() const = 0;
    // The nearest hit with t in t_range among primitives visible to ray_mask (see nearer()).
    std::optional<Hit> intersect(const Ray& ray, Interval t_range, std::uint32_t ray_mask) const {
        if (!is_traceable(ray)) return std::nullopt;
        return closest_hit(ray, t_range, ray_mask);
    }
    // The closest hits of up to kRayPacketSize rays asked together, hits[i] for rays[i], each
    // exactly what intersect() gives that ray alone: for coherent rays (a tile's eye rays), which
    // a BVH traces as a packet.
    void intersect_packet(std::span<const Ray> rays, Interval t_range, std::uint32_t ray_mask,
                          std::optional<Hit>* hits) const;
    // Whether any primitive visible to ray_mask is hit with t in t_range (shadow feelers).
    bool occluded(const Ray& ray, Interval t_range, std::uint32_t ray_mask) const {
        return is_traceable(ray) && any_hit(ray, t_range, ray_mask);
    }
    // occluded() for up to kRayPacketSize rays asked together (feelers from neighbouring points
    // towards one light), each over its own t_ranges[i]: bit i of the result for rays[i].
    unsigned occluded_packet(std::span<const Ray> rays, const Interval* t_ranges,
                             std::uint32_t ray_mask) const;
    // Memory the structure takes beyond the primitives themselves, in bytes.
    virtual std::size_t memory_bytes() const = 0;
    // Its nodes, leaves, depth, SAH cost and memory (accel_stats.h), walked from the structure
    // as built: for `glint info`, not for the hot path.
    virtual AccelStats statistics() const = 0;

protected:
    // intersect() and occluded() for a traceable ray.
    virtual std::optional<Hit> closest_hit(const Ray& ray, Interval t_range,
                                           std::uint32_t ray_mask) const = 0;
    virtual bool any_hit(const Ray& ray, Interval t_range, std::uint32_t ray_mask) const = 0;
    // occluded_packet() for traceable rays; by default one after another.
    virtual unsigned any_hits(std::span<const Ray> rays, const Interval* t_ranges,
                              std::uint32_t ray_mask) const {
        unsigned blocked = 0;
        for (std::size_t i = 0; i < rays.size(); ++i)
            if (any_hit(rays[i], t_ranges[i], ray_mask)) blocked |= 1u << i;
        return blocked;
    }
    // intersect_packet() for traceable rays; by default one after another.
    virtual void closest_hits(std::span<const Ray> rays, Interval t_range, std::uint32_t ray_mask,
                              std::optional<Hit>* hits) const {
        for (std::size_t i = 0; i < rays.size(); ++i)
            hits[i] = closest_hit(rays[i], t_range, ray_mask);
    }
};

inline void Aggregate::intersect_packet(std::span<const Ray> rays, Interval t_range,
                                        std::uint32_t ray_mask, std::optional<Hit>* hits) const {
    assert(rays.size() <= std::size_t(kRayPacketSize));
    bool all = true;
    for (const Ray& ray : rays) all = all && is_traceable(ray);
    if (all) return closest_hits(rays, t_range, ray_mask, hits);
    // Rays that cannot hit anything leave the packet.
    PacketSubset traced;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        hits[i].reset();
        if (is_traceable(rays[i])) traced.add(i, rays[i], t_range);
    }
    if (traced.size == 0) return;
    std::array<std::optional<Hit>, kRayPacketSize> found;
    closest_hits(traced.rays_span(), t_range, ray_mask, found.data());
    for (std::size_t k = 0; k < traced.size; ++k) hits[traced.slot[k]] = found[k];
}

inline unsigned Aggregate::occluded_packet(std::span<const Ray> rays, const Interval* t_ranges,
                                           std::uint32_t ray_mask) const {
    assert(rays.size() <= std::size_t(kRayPacketSize));
    bool all = true;
    for (const Ray& ray : rays) all = all && is_traceable(ray);
    if (all) return any_hits(rays, t_ranges, ray_mask);
    // Rays that cannot hit anything leave the packet.
    PacketSubset traced;
    for (std::size_t i = 0; i < rays.size(); ++i)
        if (is_traceable(rays[i])) traced.add(i, rays[i], t_ranges[i]);
    if (traced.size == 0) return 0;
    return traced.in_packet(any_hits(traced.rays_span(), traced.ranges.data(), ray_mask));
}

}  // namespace glint
