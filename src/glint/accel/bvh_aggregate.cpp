#include "glint/accel/bvh_aggregate.h"

#include "glint/accel/rounding_margin.h"

namespace glint {

BvhAggregate::BvhAggregate(std::span<const Primitive> primitives) : refs_(primitives) {
    std::vector<Bounds3> bounds;
    std::vector<std::uint32_t> bounded;  // BVH primitive index -> reference
    for (std::uint32_t i = 0; i < refs_.size(); ++i) {
        const Bounds3 b = refs_.bounds(i);
        if (b.is_finite()) {
            bounded.push_back(i);
            bounds.push_back(b);
            bounds_ = merge(bounds_, b);
        } else {
            unbounded_.push_back(i);
        }
    }
    // Grown boxes: a hit on a box's face (a flat mesh, a shared edge) is never culled by the
    // rounding of the slab test, so ties at equal t resolve as in the list.
    const float margin = rounding_margin(bounds_);
    const Vector3 grow{margin, margin, margin};
    for (Bounds3& b : bounds) b = {b.min - grow, b.max + grow};
    bvh_ = build_bvh4(bounds);
    // Leaves name references directly: one indirection less per primitive tested.
    for (std::uint32_t& i : bvh_.primitive_indices) i = bounded[i];
}

std::optional<Hit> BvhAggregate::closest_hit(const Ray& ray, Interval t_range,
                                             std::uint32_t ray_mask) const {
    std::optional<Hit> closest;
    const auto try_primitive = [&](std::uint32_t index, Interval range) -> std::optional<float> {
        if (!refs_.visible(index, ray_mask)) return std::nullopt;
        const auto hit = refs_.intersect(index, ray, range);
        if (!hit) return std::nullopt;
        const Hit candidate{*hit, refs_[index].primitive};
        if (!closest || nearer(candidate, *closest)) closest = candidate;
        return closest->shape_hit.t;
    };
    for (const std::uint32_t index : unbounded_) {
        if (const auto t = try_primitive(index, t_range)) t_range.max = *t;
    }
    bvh_closest_hit(bvh_, ray, t_range,
                    [&](std::uint32_t i, Interval range) { return try_primitive(i, range); });
    return closest;
}

bool BvhAggregate::any_hit(const Ray& ray, Interval t_range, std::uint32_t ray_mask) const {
    const auto hits = [&](std::uint32_t index, Interval range) {
        return refs_.visible(index, ray_mask) && refs_.intersect(index, ray, range).has_value();
    };
    for (const std::uint32_t index : unbounded_) {
        if (hits(index, t_range)) return true;
    }
    return bvh_any_hit(bvh_, ray, t_range,
                       [&](std::uint32_t i, Interval range) { return hits(i, range); });
}

std::size_t BvhAggregate::memory_bytes() const {
    return sizeof(*this) + refs_.memory_bytes() + bvh_.memory_bytes() +
           unbounded_.capacity() * sizeof(std::uint32_t);
}

}  // namespace glint
