// The planar polygons of a world as beam tracing takes them: each polygon, triangle, mesh
// triangle and box face, placed by its transforms, as a region of its plane in integer
// coordinates, with what shading a point of it needs (its primitive, and the part and
// barycentric weights a hit on it carries).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "glint/geometry/shape.h"
#include "glint/render/beam/planar_region.h"

namespace glint {
class World;
}

namespace glint::beam {

struct BeamPolygon {
    PlaneFrame frame;  // its plane; frame.n is the shape's outward (geometric) normal
    Paths region;      // in frame, filled by the non-zero rule
    PlaneD plane;      // frame.n . x = d
    std::uint32_t primitive = 0;
    std::uint32_t part = 0;           // ShapeHit::part: a mesh's triangle, a box's face
    bool barycentric = false;         // a triangle: hits carry the weights of corners 1 and 2
    std::array<Vector3d, 3> corners;  // of a triangle, in world space
    bool seen = true;                 // by eye, reflected and refracted beams
    bool casts_shadows = true;
};

// Every polygon of the world's primitives, which must all be planar polygons (as
// check_integrator_fits makes sure for the beam integrator); others are left out. Integer
// coordinates have `scale` units per scene unit.
std::vector<BeamPolygon> beam_polygons(const World& world, double scale);

}  // namespace glint::beam
