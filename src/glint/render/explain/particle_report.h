// What the light integrator's particles bring to one pixel, for `glint explain`: its eye ray
// finds only emitters and the sky, so the rest of the pixel's colour comes from particles that
// other pixels' samples sent from the lights. The report traces the sample pass's particles as
// the render does (one from each pixel's sample, after its eye ray) and keeps those that land
// on the pixel.
#pragma once

#include "glint/render/explain/explain.h"
#include "glint/render/explain/ray_tree.h"
#include "glint/render/world.h"

namespace glint {

// The report of which.sample's particles on pixel (which.x, which.y); the world's integrator
// must be the light integrator.
ParticleReport particle_report(const World& world, const PixelSample& which);

}  // namespace glint
