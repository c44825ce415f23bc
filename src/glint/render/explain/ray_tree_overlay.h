// A ray tree drawn over the image it explains: every ray and shadow feeler as a segment of the
// film, where the camera sees it, so that a page can draw a clicked pixel's tree into the picture.
#pragma once

#include <vector>

#include "glint/camera/camera_spec.h"
#include "glint/math/vector.h"
#include "glint/render/explain/ray_tree.h"

namespace glint {

struct OverlaySegment {
    int node = 0;  // the ray's node in RayTree::nodes; a feeler's is the node it leaves from
    RayKind kind = RayKind::primary;
    int light = -1;        // a feeler's light: its index in the node's lights (or next events)
    bool blocked = false;  // a feeler that met something: any channel's shadow below 1
    bool missed = false;   // a ray that left the scene: drawn as far as `reach`
    Point2 from, to;       // in pixels of the image, (0, 0) at its top-left corner
};

// The segments of `tree` as the camera of `spec` (of an image `width` x `height`) sees them through
// its pinhole: each cut to the part in front of the eye, none for a part wholly behind it. A
// missed ray, or a feeler towards a directional light, is drawn `reach` long. Empty unless the
// camera is a perspective one that stands still: other projections bend straight lines.
std::vector<OverlaySegment> ray_tree_overlay(const RayTree& tree, const CameraSpec& spec, int width,
                                             int height, float reach);

}  // namespace glint
