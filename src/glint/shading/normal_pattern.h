// Normal patterns as POV-Ray's `normal { }` defines them: a vector field added to the unit
// normal, then normalised, in the pattern's own space. Bumps are Perlin's original bump mapping
// (Perlin 1985, "An Image Synthesizer": N + DNoise(P)); any solid pattern tilts the normal down
// its slope, which is Blinn's bump mapping with the pattern as the height field.
#pragma once

#include <memory>

#include "glint/math/transform.h"
#include "glint/math/vector.h"
#include "glint/shading/pattern.h"
#include "glint/shading/texture.h"

namespace glint {

enum class NormalPatternKind {
    bumps,     // amount * vector noise
    dents,     // amount * noise^3 * vector noise: bumps where the noise is high, smooth elsewhere
    wrinkles,  // amount * sum over 10 octaves of |vector noise(2^i p)| / 2^i, per component
    ripples,   // rings of sin(2 pi (d frequency + phase)) round 10 points on the unit sphere
    waves,     // ripples with each source's own frequency, and amplitudes falling with it
    slope,     // down the slope of `pattern` (or of `pigment`'s grey): -(2/15) amount grad, by
               // differences
};

struct NormalPattern {
    NormalPatternKind kind = NormalPatternKind::bumps;
    // slope: the pattern; every kind: its turbulence; ripples and waves: its frequency and
    // phase.
    PatternSpec pattern;
    // slope: a colour source whose grey (0.297 r + 0.589 g + 0.114 b, POV-Ray's) is the height,
    // in place of `pattern`: POV-Ray's pigment_pattern. Lies in the pattern's space.
    std::shared_ptr<const Texture> pigment;
    float amount = 0.5f;     // POV-Ray's bump_size
    float accuracy = 0.02f;  // slope: the step of the differences, > 0
    Transform to_pattern;    // scene space to the pattern's
};

// The vector the pattern adds to the unit normal at q, in the pattern's space, before the sum
// is normalised. Exposed for tests; perturbed() is what shading calls.
Vector3 normal_offset(const NormalPattern& pattern, Point3 q);

// The unit normal n at the scene point p, tilted by the pattern: in the pattern's space
// normalize(n + offset), and back. Tilted at most kMaxBumpTiltDegrees there, and never past
// the tangent plane; n as it is where the offset is zero or not finite.
Normal3 perturbed(const NormalPattern& pattern, Normal3 n, Point3 p);

}  // namespace glint
