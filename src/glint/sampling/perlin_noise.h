// Ken Perlin's improved gradient noise: a smooth random function of space, for solid textures
// (shading/noise.h builds on it) and for the noise of implicit surfaces' expressions.
#pragma once

#include "glint/math/vector.h"

namespace glint {

// Ken Perlin's improved noise (Perlin 2002, "Improving Noise"): gradient noise on the integer
// lattice with the quintic fade 6t^5 - 15t^4 + 10t^3 and the 12 cube-edge gradients. Range about
// [-1, 1] (2e6 samples reach +-1.006), gradient length below 3.5, 0 at every lattice point,
// C2-continuous, period 256 in each axis. Defined for every finite point; a NaN or infinite
// coordinate gives 0.
float perlin_noise(Point3 p);

// The exact gradient of perlin_noise at p, for bump mapping; 0 for a non-finite p.
Vector3 perlin_noise_gradient(Point3 p);

}  // namespace glint
