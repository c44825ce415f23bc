// An image carried onto surfaces by a projection of space, as POV-Ray's image_map does: from the
// x-y plane straight along z (planar), from a sphere or a cylinder round y through the origin.
// The point is taken into the projection's space first, so the image is placed as patterns are.
#pragma once

#include <optional>

#include "glint/math/transform.h"
#include "glint/shading/image_texture.h"

namespace glint {

enum class ImageProjection {
    planar,       // u = x, v = y: the image's unit square in the x-y plane, seen along z
    spherical,    // u the longitude round y from +x towards +z, v from the south pole (0) up
    cylindrical,  // u as spherical's, v = y: once round a cylinder of height 1 standing on y = 0
};

struct ProjectedImage {
    ImageTexture image;  // its wrap: repeat, or clamp for `once`
    ImageProjection projection = ImageProjection::planar;
    // One copy of the image in [0, 1) x [0, 1) of (u, v); elsewhere `outside` (POV-Ray's pigment is
    // clear there: glint's material has one transmit).
    bool once = false;
    Color outside;
    Transform to_projection;  // scene space to the projection's
};

// The image coordinates of the point q (in the projection's space), before wrapping; nothing
// where they are undefined (the origin for the sphere, the y axis for the cylinder) or, with
// `once`, off the image.
std::optional<Point2> projected_uv(ImageProjection projection, bool once, Point3 q);

// The image's colour at the scene point p; `outside` where projected_uv gives nothing.
Color evaluate(const ProjectedImage& texture, Point3 p);

}  // namespace glint
