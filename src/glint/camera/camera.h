// Primary rays from a CameraSpec and an image size: pinhole perspective or orthographic.
#pragma once

#include "glint/camera/camera_spec.h"
#include "glint/math/ray.h"

namespace glint {

class Camera {
public:
    // The spec must be valid (see CameraSpec); the aspect ratio comes from width / height.
    Camera(const CameraSpec& spec, int width, int height);

    // The ray through a film position given in pixels: (0, 0) is the top-left corner of the
    // image and (width, height) the bottom-right one. The direction is unit length.
    Ray generate_ray(Point2 film) const;

    Point3 eye() const { return eye_; }

private:
    Projection projection_;
    Point3 eye_;
    // View reference frame (the notes' u, v, n): right, up, and forward (towards look-at).
    Vector3 u_, v_, n_;
    float half_width_, half_height_;  // of the window at distance 1 (perspective) or in units
    float width_, height_;            // of the image, in pixels
};

}  // namespace glint
