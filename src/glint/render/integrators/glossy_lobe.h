// Cook's glossy reflection and translucency: a rough surface spreads the reflected (or
// refracted) ray over a lobe around the mirror (or Snell) direction instead of tracing that one
// direction. Each sample takes one direction drawn from the normalised Phong lobe
// (n+1)/(2 pi) cos^n(alpha), so the pixel's mean converges to the lobe-weighted integral of
// the light arriving, with weight 1 per ray. A direction that the lobe tips through the surface
// brings nothing: the surface itself blocks it.
#pragma once

#include "glint/math/vector.h"
#include "glint/sampling/warp.h"
#include "glint/shading/roughness.h"

namespace glint {

// The direction a sample drawn from u takes around the unit direction `ideal`, for a surface of
// the given roughness and geometric normal ng (on the ray's side). `outward` says whether the
// ray stays on ng's side (reflection) or crosses to the other (refraction). The zero vector
// when the drawn direction is on the wrong side of the surface (kBlockedByTheSurface; an
// std::optional here made GCC read it back through a store-forwarding stall, 3% of a render).
inline constexpr Vector3 kBlockedByTheSurface{0, 0, 0};

inline Vector3 spread_over_lobe(Vector3 ideal, float roughness, Point2 u, Vector3 ng,
                                bool outward) {
    if (roughness < kMirrorRoughness) return ideal;
    const Vector3 d =
        from_frame(sample_phong_lobe(u, phong_exponent_of_roughness(roughness)), ideal);
    const float side = dot(d, ng);
    if (outward ? side <= 0 : side >= 0) return kBlockedByTheSurface;
    return d;
}

}  // namespace glint
