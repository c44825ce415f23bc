// A material's roughness as a Phong lobe: how wide a rough surface spreads the rays it reflects
// or refracts around the mirror or Snell direction, for every integrator that samples lobes.
#pragma once

namespace glint {

// Below this roughness a lobe is so narrow that the mirror direction is traced: exponent 2e6.
inline constexpr float kMirrorRoughness = 1e-3f;

// The Phong exponent of a roughness r in (0, 1]: n = 2 / r^2 - 2, the exponent whose lobe is
// as wide as the Beckmann microfacet distribution of slope r (Walter et al. 2007), so that
// r = 1 spreads over the whole hemisphere (n = 0) and r = 0.1 is a blurred mirror (n = 198).
constexpr float phong_exponent_of_roughness(float r) { return 2 / (r * r) - 2; }

}  // namespace glint
