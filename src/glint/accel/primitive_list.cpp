// The brute-force list: every primitive against every ray, the reference the others match.
#include "glint/accel/primitive_list.h"

namespace glint {

PrimitiveList::PrimitiveList(std::span<const Primitive> primitives) : refs_(primitives) {
    for (const Primitive& p : primitives) {
        const Bounds3 b = glint::bounds(p.shape);
        if (b.is_finite()) bounds_ = merge(bounds_, b);
    }
}

std::optional<Hit> PrimitiveList::closest_hit(const Ray& ray, Interval t_range,
                                              std::uint32_t ray_mask) const {
    std::optional<Hit> closest;
    for (std::uint32_t i = 0; i < refs_.size(); ++i) {
        if (!refs_.visible(i, ray_mask)) continue;
        if (const auto hit = refs_.intersect(i, ray, t_range)) {
            // In reference order, a hit at an equal t is never nearer (see nearer()).
            if (closest && hit->t == closest->shape_hit.t) continue;
            closest = Hit{*hit, refs_[i].primitive};
            t_range.max = hit->t;  // only nearer hits from now on
        }
    }
    return closest;
}

bool PrimitiveList::any_hit(const Ray& ray, Interval t_range, std::uint32_t ray_mask) const {
    for (std::uint32_t i = 0; i < refs_.size(); ++i)
        if (refs_.visible(i, ray_mask) && refs_.intersect(i, ray, t_range)) return true;
    return false;
}

AccelStats PrimitiveList::statistics() const {
    std::size_t unbounded = 0;
    for (std::uint32_t i = 0; i < refs_.size(); ++i) unbounded += !refs_.bounds(i).is_finite();
    AccelStatsTally tally(bounds_);
    tally.leaf(bounds_, 0, refs_.size() - unbounded);
    return tally.finish(unbounded, memory_bytes());
}

}  // namespace glint
