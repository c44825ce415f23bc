// Primary rays from a CameraSpec and an image size: pinhole or thin-lens perspective, or
// orthographic, standing still or moving.
#pragma once

#include <memory>

#include "glint/camera/camera_spec.h"
#include "glint/math/animated_transform.h"
#include "glint/math/ray.h"

namespace glint {

class Camera {
public:
    // The spec must be valid (see CameraSpec); the aspect ratio comes from width / height.
    Camera(const CameraSpec& spec, int width, int height);

    // The ray through a film position given in pixels: (0, 0) is the top-left corner of the
    // image and (width, height) the bottom-right one. `lens` in [0,1)^2 picks the point of the
    // aperture (ignored by a pinhole), `time` the moment (see shutter_time). The direction is
    // unit length.
    Ray generate_ray(Point2 film, Point2 lens = {0.5f, 0.5f}, float time = 0) const;

    // Whether eye rays need lens numbers (an aperture) and time numbers (an open shutter).
    bool has_lens() const { return lens_radius_ > 0; }
    bool has_shutter() const { return shutter_close_ > shutter_open_; }
    // The moment u in [0, 1) stands for: uniform over the shutter interval.
    float shutter_time(float u) const {
        return shutter_open_ + u * (shutter_close_ - shutter_open_);
    }
    float shutter_open() const { return shutter_open_; }

    // The point on the unit disk, or the regular polygon inscribed in it, that u picks: where on
    // the aperture (in units of its radius) a ray starts.
    Point2 aperture_point(Point2 u) const;

    Point3 eye() const { return eye_; }

private:
    Projection projection_;
    Point3 eye_;
    // View reference frame (the notes' u, v, n): right, up, and forward (towards look-at). For
    // a moving camera the frame is the camera's own, and motion_ places it in the world.
    Vector3 u_, v_, n_;
    float half_width_, half_height_;  // of the window at distance 1 (perspective) or in units
    float width_, height_;            // of the image, in pixels
    float lens_radius_, focus_distance_;
    int blades_;
    float blade_rotation_;  // radians
    float shutter_open_, shutter_close_;
    std::shared_ptr<const AnimatedTransform> motion_;  // world from camera; null: static
};

// The view frame of from, at and up as a transform from camera space (x right, y up, z
// forward, eye at the origin) to the world. It mirrors: the notes' u, v, n are left-handed.
Transform world_from_camera(Point3 from, Point3 at, Vector3 up);

}  // namespace glint
