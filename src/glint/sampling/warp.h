// Warps: maps from uniform numbers u in [0,1)^2 to points and directions with a known density,
// for the distributed ray tracer's apertures, lights, glossy lobes and wavelengths.
// Every warp returns finite values for every u in [0,1)^2, including u = (0, 0).
#pragma once

#include "glint/math/constants.h"
#include "glint/math/vector.h"

namespace glint {

// Uniform on the unit disk by Shirley and Chiu's concentric map (1997, "A Low Distortion Map
// Between Disk and Square"): nested squares go to nested circles, so stratified u stay
// stratified. Density 1/pi per unit area.
Point2 sample_uniform_disk(Point2 u);
constexpr float uniform_disk_pdf() { return 1 / kPi; }

// The regular polygon with `sides` >= 3 vertices on the unit circle, the first at angle
// `rotation_radians` from +x, counter-clockwise: its area, n/2 sin(2 pi/n).
float regular_polygon_area(int sides);
// Uniform by area inside that polygon (a camera's polygonal aperture): u.x picks one of the
// `sides` equal wedges (centre, vertex k, vertex k+1) and, re-stretched, samples it with u.y.
// Density 1 / regular_polygon_area(sides).
Point2 sample_regular_polygon(Point2 u, int sides, float rotation_radians);

// Barycentric coordinates (b0, b1), b2 = 1 - b0 - b1, uniform over any triangle, by Heitz's
// low-distortion map (2019, "A Low-Distortion Map Between Triangle and Square"): both halves
// of the square map linearly onto the two halves of the triangle. b0, b1 >= 0, b0 + b1 < 1.
Point2 sample_uniform_triangle(Point2 u);

// Uniform over the unit sphere: z = 1 - 2 u.x is uniform (Archimedes' hat-box theorem).
Vector3 sample_uniform_sphere(Point2 u);
constexpr float uniform_sphere_pdf() { return 1 / (4 * kPi); }

// Unit directions within angle acos(cos_max) of +z, uniform in solid angle: what a sphere light
// subtends from a point outside it. cos_max in [-1, 1); density 1 / (2 pi (1 - cos_max)).
Vector3 sample_uniform_cone(Point2 u, float cos_max);
constexpr float uniform_cone_pdf(float cos_max) { return 1 / (2 * kPi * (1 - cos_max)); }

// The normalised Phong lobe around +z: density (n+1)/(2 pi) cos^n(alpha) per steradian for
// cos(alpha) >= 0 and 0 below, n = exponent >= 0 and finite (Cook, Porter and Carpenter 1984
// spread glossy rays with it; Lafortune and Willems 1994 sample it by cos(alpha) =
// u^(1/(n+1)), here with 1 - u.x for u so that cos(alpha) > 0 and every sample has pdf > 0).
// Exponent 0 is the uniform hemisphere; exponents of 1e6 stay accurate.
Vector3 sample_phong_lobe(Point2 u, float exponent);
float phong_lobe_pdf(float cos_alpha, float exponent);

// `local` expressed in a right-handed orthonormal frame whose z axis is the unit vector `axis`
// (x and y from glint::orthonormal_basis): turns a lobe or cone around +z to any direction.
Vector3 from_frame(Vector3 local, Vector3 axis);

// Wavelengths in nanometres on [360, 830] with density proportional to
// 1 / cosh^2(0.0072 (lambda - 538)), the smooth fit to the eye's sensitivity that pbrt-v4
// uses for spectral rendering. Its CDF, tanh(0.0072 (lambda - 538)) rescaled, inverts in
// closed form. u in [0, 1); the pdf is 0 outside [360, 830].
float sample_visible_wavelength(float u);
float visible_wavelength_pdf(float lambda_nm);

}  // namespace glint
