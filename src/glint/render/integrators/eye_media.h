// The refracting solids that eye rays start in: from a camera under water, glass is entered from
// water's index, not from vacuum's. Decided once a render, from the places eye rays start (the
// eye, the rim of the lens, the corners of an orthographic window, both ends of the shutter).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "glint/accel/primitive.h"
#include "glint/camera/camera.h"
#include "glint/shading/material.h"

namespace glint {

struct EyeMedia {
    // The transmitting objects around the eye, outermost first (by their bounds' volume).
    std::vector<std::uint32_t> primitives;
    // What could not be decided: an object that refracts and cannot say what is inside it (an
    // open mesh) where eye rays start, or eye rays that start on both sides of a surface. Such
    // an object counts as around the eye when the centre eye ray starts inside it.
    std::vector<std::string> warnings;
};

// For a camera of an image of width x height pixels; material_of gives each primitive's index
// into materials.
EyeMedia find_eye_media(const Camera& camera, int width, int height,
                        std::span<const Primitive> primitives, std::span<const Material> materials,
                        std::span<const std::uint32_t> material_of);

}  // namespace glint
