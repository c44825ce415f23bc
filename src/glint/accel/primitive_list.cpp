#include "glint/accel/primitive_list.h"

namespace glint {

PrimitiveList::PrimitiveList(std::span<const Primitive> primitives) : primitives_(primitives) {
    for (const Primitive& p : primitives_) {
        const Bounds3 b = glint::bounds(p.shape);
        if (b.is_finite()) bounds_ = merge(bounds_, b);
    }
}

std::optional<Hit> PrimitiveList::closest_hit(const Ray& ray, Interval t_range,
                                              std::uint32_t ray_mask) const {
    std::optional<Hit> closest;
    for (std::uint32_t i = 0; i < primitives_.size(); ++i) {
        if ((primitives_[i].visibility & ray_mask) == 0) continue;
        if (const auto hit = glint::intersect(primitives_[i].shape, ray, t_range)) {
            // In index order, a hit at an equal t is never nearer (see nearer()).
            if (closest && hit->t == closest->shape_hit.t) continue;
            closest = Hit{*hit, i};
            t_range.max = hit->t;  // only nearer hits from now on
        }
    }
    return closest;
}

bool PrimitiveList::any_hit(const Ray& ray, Interval t_range, std::uint32_t ray_mask) const {
    for (const Primitive& p : primitives_)
        if ((p.visibility & ray_mask) != 0 && glint::intersect(p.shape, ray, t_range)) return true;
    return false;
}

}  // namespace glint
