// Solid textures made of Perlin noise (Perlin 1985): marble, wood, granite, turbulence and
// fractal noise carved out of space, for a material's colour (through a colour ramp), for its
// scalar parameters (reflect, roughness) and as a bump map.
#pragma once

#include <vector>

#include "glint/math/color.h"
#include "glint/math/vector.h"

namespace glint {

enum class NoisePattern { fbm, granite, marble, turbulence, wood };

// A pattern in space: value(p) in [0, 1] at the scene point p.
struct NoiseSpec {
    NoisePattern pattern = NoisePattern::marble;
    float scale = 1;       // size of one feature (a vein, a ring, a noise cell) in scene units
    float turbulence = 1;  // marble and wood: how far, in features, turbulence moves them
    int octaves = 6;       // in [1, kMaxOctaves]
};

// The pattern's value at p, in [0, 1]: marble's veins, wood's rings, granite's speckles,
// turbulence and fbm (fractal noise 0.5 + 0.5 fbm, clamped) at the point p / scale.
float noise_value(const NoiseSpec& spec, Point3 p);
// Its gradient with respect to p (analytic for turbulence and fbm, by central differences for
// the others), for bump mapping.
Vector3 noise_gradient(const NoiseSpec& spec, Point3 p);

// A colour: the pattern's value looks up an evenly spaced colour ramp.
struct NoiseTexture {
    NoiseSpec spec;
    std::vector<Color> colors;  // at least 2
};
Color evaluate(const NoiseTexture& texture, Point3 p);

// A number between low and high by the pattern: a textured reflect or roughness.
struct NoiseScalar {
    NoiseSpec spec;
    float low = 0, high = 1;
};
inline float evaluate(const NoiseScalar& s, Point3 p) {
    return s.low + (s.high - s.low) * noise_value(s.spec, p);
}

// Blinn's bump mapping with the pattern as height field: the surface seems moved along its
// normal by strength * value(p), in scene units.
struct BumpMap {
    NoiseSpec spec;
    float strength = 0.05f;
};
Normal3 bumped(const BumpMap& bump, Normal3 n, Point3 p);

}  // namespace glint
