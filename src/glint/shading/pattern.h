// Solid patterns as POV-Ray defines them: a number in [0, 1] at each point of space, shaped by
// a wave, a frequency and a phase, and disturbed by turbulence, which a colour map turns into a
// colour (pattern_texture.h). The geometric ones give POV-Ray's own values; the ones made of
// noise (agate, bozo, crackle, granite) use glint's noise, so they look alike but differ in
// detail from POV-Ray's.
#pragma once

#include <memory>
#include <span>

#include "glint/math/transform.h"
#include "glint/math/vector.h"

namespace glint {

class Expression;  // geometry/expression.h

enum class PatternKind {
    agate,        // bands along z bent by turbulence
    bozo,         // smooth noise (POV-Ray's spotted is the same)
    boxed,        // 1 - max(|x|, |y|, |z|)
    brick,        // 0 in the mortar, 1 in a brick: rows of bricks laid in running bond
    checker,      // 0 or 1 by the parity of the cells' sum (checker_cell): no wave, no frequency
    crackle,      // cells round random points: the distance to the second nearest minus the nearest
    function,     // f(x, y, z) of an expression (POV-Ray's function pattern), wrapped into [0, 1]
    cylindrical,  // 1 - sqrt(x^2 + z^2)
    gradient,     // p . direction
    granite,      // turbulent noise (noise.h)
    hexagon,      // 0, 1/2 or 1: hexagons of side 1 in the x-z plane, three colours
    leopard,      // (sin x + sin y + sin z)^2 / 9
    mandel,       // the Mandelbrot set in the x-y plane: escape iterations over the most, 1 inside
    marble,       // x, by default through the triangle wave
    onion,        // |p|
    planar,       // 1 - |y|
    radial,       // the angle round y, clockwise seen from above, over a turn
    ripples,      // rings round POV-Ray's ten wave sources, all of one frequency
    spherical,    // 1 - |p|
    spiral1,      // z + the distance from z + arms x the angle round it over a turn
    spiral2,      // the same through triangle waves, crossed
    waves,        // rings round the wave sources, each of its own frequency and amplitude
    wood,         // sqrt(x^2 + y^2), by default through the triangle wave
    wrinkles,     // noise summed over ten octaves, each half as strong and twice as fine
};

// How the value, after frequency and phase and taken modulo 1 (f), becomes the map's index.
enum class PatternWave {
    ramp,      // f
    triangle,  // 2f up to 1/2, then down
    sine,      // (1 + sin(2 pi f)) / 2
    scallop,   // |sin(pi f)|
    cubic,     // 3f^2 - 2f^3
    poly,      // f^exponent
};

struct PatternSpec {
    PatternKind kind = PatternKind::gradient;
    Vector3 direction{1, 0, 0};  // gradient: unit
    PatternWave wave = PatternWave::ramp;
    float exponent = 1;  // poly wave
    float frequency = 1, phase = 0;
    // Turbulence moves the point by this much times a vector of noise summed over octaves,
    // each omega as strong and lambda times as fine as the one before (POV-Ray's defaults).
    Vector3 turbulence{0, 0, 0};
    int octaves = 6;  // in [1, kMaxOctaves]
    float omega = 0.5f, lambda = 2;
    // Where the turbulence is a warp written after some of the pattern's transforms (POV-Ray's
    // warp { turbulence }): the point turbulence moved is taken on through the inverse of those
    // transforms into the pattern's own space.
    bool warped = false;
    Transform after_turbulence;
    // brick: a brick's size (x along the wall, y a course's height, z across it) and the
    // mortar's width, both with their mortar; POV-Ray's defaults.
    Vector3 brick_size{8, 3, 4.5f};
    float mortar = 0.5f;
    int iterations = 1;                          // mandel: the most iterations, >= 1
    float arms = 1;                              // spiral1, spiral2
    std::shared_ptr<const Expression> function;  // function: f, not null
};

// The centres of POV-Ray's waves and ripples: ten points spread evenly over the unit sphere (a
// Fibonacci spiral, glint's own) with POV-Ray's own wave frequencies in [0.01, 1.01].
struct WaveSource {
    Vector3 at;
    float frequency;
};
std::span<const WaveSource> wave_sources();

// Whether the pattern picks one of a few colours, as POV-Ray's list patterns do: its value is
// not shaped by a wave, frequency or phase.
bool is_list_pattern(PatternKind kind);

// POV-Ray's default wave for the kind: triangle for marble, wood and the spirals, ramp for the
// others.
PatternWave default_wave(PatternKind kind);

// The point p moved by the spec's turbulence (p itself without turbulence).
Point3 turbulent(const PatternSpec& spec, Point3 p);

// The pattern's value at p (in the pattern's own space), in [0, 1]; 0 at a non-finite point.
float pattern_value(const PatternSpec& spec, Point3 p);

// The index of the checker cell that v (in cells) lies in. A face lying on a cell boundary, a
// box's side at x = 1, falls into one cell rather than into either by the rounding of its
// points: every boundary sits 1e-6 of a cell low, past float's rounding of the point.
double checker_cell(double v);

}  // namespace glint
