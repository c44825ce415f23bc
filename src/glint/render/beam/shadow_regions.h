// Where each light reaches each polygon: the polygon minus the shadows the others cast on its
// plane, each occluder projected from the light (Atherton, Weiler and Greenberg's shadow
// polygons, 1978, which Heckbert and Hanrahan's beam tracer used for its light beams). Shadows
// then have exact edges in the beam-traced image as polygons do. An area light casts the hard
// shadow of its centre, as in Whitted's ray tracer.
#pragma once

#include <span>
#include <vector>

#include "glint/render/beam/beam_polygons.h"
#include "glint/shading/light.h"

namespace glint::beam {

struct LightReach {
    bool everywhere = true;  // nothing shadows the polygon: lit is its whole region
    Paths lit;               // in the polygon's frame, when not everywhere
};

// reach[light][polygon]. Points within `tolerance` of a polygon's plane do not shadow it.
std::vector<std::vector<LightReach>> light_reach(std::span<const Light> lights,
                                                 std::span<const BeamPolygon> polygons,
                                                 double tolerance);

}  // namespace glint::beam
