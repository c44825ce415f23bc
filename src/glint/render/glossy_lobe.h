// Cook's glossy reflection and translucency: a rough surface spreads the reflected (or
// refracted) ray over a lobe around the mirror (or Snell) direction instead of tracing that one
// direction. Each sample takes one direction drawn from the normalised Phong lobe
// (n+1)/(2 pi) cos^n(alpha), so the pixel's mean converges to the lobe-weighted integral of
// the light arriving, with weight 1 per ray. A direction that the lobe tips through the surface
// brings nothing: the surface itself blocks it.
#pragma once

#include "glint/math/vector.h"
#include "glint/sampling/warp.h"

namespace glint {

// Below this roughness a lobe is so narrow that the mirror direction is traced: exponent 2e6.
inline constexpr float kMirrorRoughness = 1e-3f;

// The Phong exponent of a roughness r in (0, 1]: n = 2 / r^2 - 2, the exponent whose lobe is
// as wide as the Beckmann microfacet distribution of slope r (Walter et al. 2007), so that
// r = 1 spreads over the whole hemisphere (n = 0) and r = 0.1 is a blurred mirror (n = 198).
constexpr float phong_exponent_of_roughness(float r) { return 2 / (r * r) - 2; }

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
