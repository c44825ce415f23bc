// How far primitive bounds are grown so that rounding never culls a hit the exact test finds.
#pragma once

#include <cmath>

#include "glint/math/bounds.h"

namespace glint {

// Largest absolute coordinate of a box: rounding of positions is relative to it.
inline float magnitude(const Bounds3& b) {
    return max_component(max(abs(to_vector(b.min)), abs(to_vector(b.max))));
}

// 2^-20 of the scene's largest coordinate (8 ulps). A structure whose boxes are grown by this
// margin sees every hit a shape reports strictly inside the box of that shape, whatever the
// rounding of t in the shapes and in the slab or plane tests; and a flat scene gets boxes of
// positive thickness. Kept well under the offset of a spawned ray (World::ray_epsilon, 1e-5 of
// the same magnitude or more): a ray leaving a flat face starts outside that face's box, so it is
// not tested against the face it leaves. Never zero: a scene in one point at the origin gets 1.
inline float rounding_margin(const Bounds3& scene) {
    const float margin = magnitude(scene) * 0x1p-20f;
    return margin > 0 && std::isfinite(margin) ? margin : 1;
}

}  // namespace glint
