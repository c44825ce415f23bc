// Procedural noise for solid textures: Perlin's gradient noise and its sums (fBm, turbulence),
// the classic patterns built on them (marble, wood, granite), colour ramps and bump mapping.
#pragma once

#include <span>

#include "glint/math/color.h"
#include "glint/math/vector.h"
#include "glint/sampling/perlin_noise.h"

namespace glint {

// Three of those noises far apart in space: a random vector field, each component in about
// [-1, 1] (Perlin's DNoise), for turbulence and for bumps.
Vector3 vector_noise(Point3 p);

// The most octaves a sum adds up: with gain 1/2 a float sum stops changing after 25.
inline constexpr int kMaxOctaves = 30;

// Fractional Brownian motion (Musgrave, in Ebert et al., "Texturing and Modeling"):
// sum over i < octaves of gain^i * perlin_noise(lacunarity^i * p). octaves <= 0 gives 0;
// octaves is capped at kMaxOctaves, and the sum stops early once lacunarity^i or gain^i
// overflows.
float fractal_sum(Point3 p, int octaves, float lacunarity = 2, float gain = 0.5f);
Vector3 fractal_sum_gradient(Point3 p, int octaves, float lacunarity = 2, float gain = 0.5f);

// Perlin's turbulence (Perlin 1985, "An Image Synthesizer"): sum over i < octaves of
// |perlin_noise(2^i p)| / 2^i. Always >= 0 and below twice the noise's largest magnitude (in
// practice below 1.4); octaves capped as for fractal_sum.
float turbulence(Point3 p, int octaves);
// Its gradient, sum of sign(noise_i) * gradient(noise_i): exact except on the creases where one
// octave's noise is 0, where turbulence has no derivative and the sum counts that octave as 0.
Vector3 turbulence_gradient(Point3 p, int octaves);

// Central differences of any scalar field f(Point3) -> float, for patterns without an analytic
// gradient: (f(p + h e_i) - f(p - h e_i)) / (the step actually taken in float). h > 0, in the
// units of p; the error is O(h^2) plus f's rounding over 2h.
template <typename F>
Vector3 gradient_of(F f, Point3 p, float h) {
    auto along = [&](Vector3 axis) {
        const Point3 forward = p + axis * h, back = p - axis * h;
        const float step = dot(forward - back, axis);
        return step > 0 ? (f(forward) - f(back)) / step : 0.0f;
    };
    return {along({1, 0, 0}), along({0, 1, 0}), along({0, 0, 1})};
}

// The patterns take a point in texture space (the caller scales and transforms) and return a
// value in [0, 1] (0 for a non-finite point), meant to index a colour ramp.

// Perlin's marble (Perlin 1985; Ebert et al., "Texturing and Modeling", ch. 2): veins across x,
// 0.5 + 0.5 sin(2 pi (p.x + turbulence_amount * turbulence(p, octaves))). One vein per unit of
// x; turbulence_amount is how far, in veins, the turbulence pushes them about.
float marble_pattern(Point3 p, float turbulence_amount, int octaves);

// Wood (Ebert et al., "Texturing and Modeling", ch. 2): rings around the y axis, one per unit of
// radius, disturbed by turbulence: frac(sqrt(x^2 + z^2) + turbulence_amount * turbulence(p)).
float wood_pattern(Point3 p, float turbulence_amount, int octaves);

// Granite (POV-Ray's granite pattern: a 1/f sum of noise magnitudes, as in Ebert et al.,
// "Texturing and Modeling"): high-frequency turbulence, sum over i < octaves of
// |0.5 - noise01(4 * 2^i p)| / 2^i with noise01 = (1 + perlin_noise) / 2, i.e. turbulence(4p) / 2,
// clamped to [0, 1]. Kept unscaled so that colour maps written for it read alike: values mostly
// fall in [0.1, 0.4] and rarely pass 0.6.
float granite_pattern(Point3 p, int octaves);

// Piecewise-linear colour between evenly spaced stops: stops[0] at t = 0, stops.back() at t = 1.
// t is clamped to [0, 1]; NaN gives the first stop. No stops give black.
Color ramp(std::span<const Color> stops, float t);

inline constexpr float kMaxBumpTiltDegrees = 89;

// Bump mapping (Blinn 1978, "Simulation of Wrinkled Surfaces") for a solid height field h whose
// gradient at the point is height_gradient: the surface moved by strength * h along the unit
// normal n has the normal normalize(n - strength * (g - (g.n) n)). The result is unit and tilted
// at most kMaxBumpTiltDegrees from n, so it never reaches the tangent plane or flips; a zero or
// non-finite perturbation leaves n as it is.
Normal3 bump_normal(Normal3 n, Vector3 height_gradient, float strength);

}  // namespace glint
