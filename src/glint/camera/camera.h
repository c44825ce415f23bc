// Primary rays from a CameraSpec and an image size: pinhole or thin-lens perspective,
// orthographic or one of the wide projections, standing still or moving.
#pragma once

#include <memory>
#include <optional>

#include "glint/camera/camera_spec.h"
#include "glint/math/animated_transform.h"
#include "glint/math/ray.h"

namespace glint {

class Camera {
public:
    // The spec must be valid (see CameraSpec); the aspect ratio comes from width / height
    // unless the spec gives its own.
    Camera(const CameraSpec& spec, int width, int height);

    // The ray through a film position given in pixels: (0, 0) is the top-left corner of the
    // image and (width, height) the bottom-right one. `lens` in [0,1)^2 picks the point of the
    // aperture (ignored by a pinhole), `time` the moment (see shutter_time). The direction is
    // unit length.
    Ray generate_ray(Point2 film, Point2 lens = {0.5f, 0.5f}, float time = 0) const;
    // The same from the point of the aperture `lens` picks (aperture_point(lens); any point for a
    // pinhole).
    Ray generate_ray_from_aperture(Point2 film, Point2 aperture, float time) const;
    // Whether the film position sees anything: not outside a fisheye's circle, where samples
    // are black.
    bool sees(Point2 film) const;

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

    // A static perspective camera's pinhole frame: the eye, the unit right, up and forward
    // directions, and the half-size of the window at distance 1. The film position of a point p
    // at d = p - eye is ((d.u / d.n / half_width + 1) width / 2, (1 - d.v / d.n / half_height)
    // height / 2): what beam tracing projects polygons with.
    struct Pinhole {
        Point3 eye;
        Vector3 u, v, n;
        float half_width, half_height;
    };
    Pinhole pinhole() const { return {eye_, u_, v_, n_, half_width_, half_height_}; }

    // What a point seen by the camera needs to be splatted onto the film (light tracing): the
    // film position the ray from a point of the lens through it lands on, that lens point, and
    // We / pdf, the camera's importance for the direction over the density of the lens point as
    // seen from the point: 1 / (A cos^3(theta) d^2) for a window of area A at distance 1, theta
    // the angle to the view axis and d the distance (the lens's area cancels). Nothing when
    // the point is behind the camera, or for an orthographic camera, which sees each point
    // along one direction only and so can never be connected to. The film position may lie
    // outside the image.
    struct Connection {
        Point2 film;        // in pixels
        Point3 lens;        // world space
        Vector3 to_camera;  // unit, from the point to the lens point
        float distance;
        float importance;  // We / pdf
    };
    std::optional<Connection> connect(Point3 p, Point2 lens, float time) const;
    // Whether connect() can ever answer: a perspective camera.
    bool is_connectable() const { return projection_ == Projection::perspective; }

private:
    Ray wide_ray(float a, float b) const;

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
    // The wide projections: the view's width over its height, the angles in radians and the
    // cylinder's extent along its axis.
    float aspect_, angle_, vertical_angle_, extent_;
    bool cylinder_axis_across_, cylinder_parallel_;
    std::shared_ptr<const AnimatedTransform> motion_;  // world from camera; null: static
};

// The view frame of from, at and up as a transform from camera space (x right, y up, z
// forward, eye at the origin) to the world. It mirrors: the notes' u, v, n are left-handed.
Transform world_from_camera(Point3 from, Point3 at, Vector3 up);

}  // namespace glint
