// Particles leaving the lights, for the integrators that trace light forwards (the notes'
// backward ray tracing, photon mapping): each starts at a point of a light, goes one way, and
// carries the share of the light's power it stands for, Le |cos| / (pdf of the point x pdf of
// the direction) over the probability its light was picked with. Lights keep their meaning: a
// light of intensity I_L (its colour, attenuated) gives irradiance pi I_L facing it, so a point
// or area light falling off as colour / (quadratic d^2) has the intensity pi colour / quadratic
// W/sr in every direction (light.h).
#pragma once

#include "glint/math/color.h"
#include "glint/math/vector.h"
#include "glint/shading/light.h"
#include "glint/shading/object_light.h"
#include "glint/shading/sky.h"

namespace glint {

struct EmittedParticle {
    Point3 origin;
    Vector3 direction;  // unit
    Color power;        // the flux it carries, before dividing by its light's pick probability
};

// The scene's bounding sphere: where particles from directional lights and the sky start, on a
// disk of its radius outside it.
struct SceneSphere {
    Point3 center;
    float radius = 1;
};

// A particle of a light that emits finite power (emits_finite_power): from u_position (which
// point of an area light, or of the disk a directional light's particles start on) and
// u_direction. An area light's point is uniform over its shape, a sphere's all round.
EmittedParticle emit_particle(const Light& light, Point2 u_position, Point2 u_direction,
                              const SceneSphere& scene);
// An emitting object's: a point drawn on it, a side (both sides of a two-sided one emit), and a
// direction cosine-weighted around that side's normal.
EmittedParticle emit_particle(const ObjectLight& light, Point2 u_position, Point2 u_direction);
// The sky's: a direction drawn by the sky's brightness (Sky::sample), entering the scene's
// sphere through the disk across it, carrying L(w) pi R^2 / pdf(w).
EmittedParticle emit_sky_particle(const Sky& sky, Point2 u_position, Point2 u_direction,
                                  const SceneSphere& scene);
// The flux the sky sends into the scene's sphere: its mean radiance x 4 pi x pi R^2.
Color sky_power(const Sky& sky, const SceneSphere& scene);

// A point drawn uniformly by area over the light's shape, as particles leave it (for an area
// light: a sphere all round, where sample_light aims at the cap it shows p), as a light sample
// for p; lights without a shape as sample_light.
LightSample sample_light_by_area(const Light& light, Point3 p, Point2 u);

}  // namespace glint
