// The brute-force aggregate: every ray against every primitive, and every triangle of a mesh
// (see PrimitiveRefs). The reference that every acceleration structure must agree with, and the
// notes' "simple method".
#pragma once

#include <span>

#include "glint/accel/aggregate.h"
#include "glint/accel/primitive_refs.h"

namespace glint {

class PrimitiveList final : public Aggregate {
public:
    explicit PrimitiveList(std::span<const Primitive> primitives);

    Bounds3 bounds() const override { return bounds_; }
    std::size_t memory_bytes() const override { return sizeof(*this) + refs_.memory_bytes(); }
    // One leaf at the root holding every bounded reference; planes are counted as unbounded.
    AccelStats statistics() const override;

private:
    std::optional<Hit> closest_hit(const Ray& ray, Interval t_range,
                                   std::uint32_t ray_mask) const override;
    bool any_hit(const Ray& ray, Interval t_range, std::uint32_t ray_mask) const override;

    PrimitiveRefs refs_;
    Bounds3 bounds_;
};

}  // namespace glint
