#include "glint/accel/bvh_aggregate.h"

#include "glint/accel/rounding_margin.h"

namespace glint {

BvhAggregate::BvhAggregate(std::span<const Primitive> primitives) : primitives_(primitives) {
    std::vector<Bounds3> bounds;
    for (std::uint32_t i = 0; i < primitives.size(); ++i) {
        const Bounds3 b = glint::bounds(primitives[i].shape);
        if (b.is_finite()) {
            bounded_.push_back(i);
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
    bvh_ = build_bvh(bounds);
}

std::optional<Hit> BvhAggregate::closest_hit(const Ray& ray, Interval t_range,
                                             std::uint32_t ray_mask) const {
    std::optional<Hit> closest;
    const auto try_primitive = [&](std::uint32_t index, Interval range) -> std::optional<float> {
        const Primitive& p = primitives_[index];
        if ((p.visibility & ray_mask) == 0) return std::nullopt;
        const auto hit = glint::intersect(p.shape, ray, range);
        if (!hit) return std::nullopt;
        const Hit candidate{*hit, index};
        if (!closest || nearer(candidate, *closest)) closest = candidate;
        return closest->shape_hit.t;
    };
    for (const std::uint32_t index : unbounded_) {
        if (const auto t = try_primitive(index, t_range)) t_range.max = *t;
    }
    bvh_closest_hit(bvh_, ray, t_range, [&](std::uint32_t i, Interval range) {
        return try_primitive(bounded_[i], range);
    });
    return closest;
}

bool BvhAggregate::any_hit(const Ray& ray, Interval t_range, std::uint32_t ray_mask) const {
    const auto hits = [&](std::uint32_t index, Interval range) {
        const Primitive& p = primitives_[index];
        return (p.visibility & ray_mask) != 0 && glint::intersect(p.shape, ray, range).has_value();
    };
    for (const std::uint32_t index : unbounded_) {
        if (hits(index, t_range)) return true;
    }
    return bvh_any_hit(bvh_, ray, t_range,
                       [&](std::uint32_t i, Interval range) { return hits(bounded_[i], range); });
}

std::size_t BvhAggregate::memory_bytes() const {
    return sizeof(*this) + bvh_.nodes.capacity() * sizeof(BvhNode) +
           bvh_.primitive_indices.capacity() * sizeof(std::uint32_t) +
           (bounded_.capacity() + unbounded_.capacity()) * sizeof(std::uint32_t);
}

}  // namespace glint
