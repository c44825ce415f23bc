// The view-reference frame (n towards the target, u right, v up), the eye ray through a film
// position for each projection, the thin lens and the moving camera.
#include "glint/camera/camera.h"

#include <algorithm>
#include <cmath>

#include "glint/math/constants.h"
#include "glint/sampling/warp.h"

namespace glint {

namespace {

struct Frame {
    Vector3 u, v, n;
};

Frame view_frame(Point3 from, Point3 at, Vector3 up) {
    Frame f;
    f.n = normalize(at - from);
    f.u = normalize(cross(f.n, up));  // right-handed: right = forward x up
    f.v = cross(f.u, f.n);
    return f;
}

}  // namespace

Transform world_from_camera(Point3 from, Point3 at, Vector3 up) {
    const Frame f = view_frame(from, at, up);
    Matrix4 m;
    m.m = {{{f.u.x, f.v.x, f.n.x, from.x},
            {f.u.y, f.v.y, f.n.y, from.y},
            {f.u.z, f.v.z, f.n.z, from.z},
            {0, 0, 0, 1}}};
    // An orthonormal frame: its inverse is its transpose, with the eye moved back to the origin.
    Matrix4 inv;
    inv.m = {{{f.u.x, f.u.y, f.u.z, -dot(f.u, to_vector(from))},
              {f.v.x, f.v.y, f.v.z, -dot(f.v, to_vector(from))},
              {f.n.x, f.n.y, f.n.z, -dot(f.n, to_vector(from))},
              {0, 0, 0, 1}}};
    return {m, inv};
}

Camera::Camera(const CameraSpec& spec, int width, int height)
    : projection_(spec.projection),
      eye_(spec.from),
      width_(static_cast<float>(width)),
      height_(static_cast<float>(height)),
      lens_radius_(spec.lens.radius),
      focus_distance_(spec.lens.focus_distance > 0 ? spec.lens.focus_distance
                                                   : distance(spec.from, spec.at)),
      blades_(spec.lens.blades),
      blade_rotation_(radians(spec.lens.blade_rotation)),
      shutter_open_(spec.shutter_open),
      shutter_close_(spec.shutter_close),
      aspect_(spec.aspect > 0 ? spec.aspect : width_ / height_),
      angle_(radians(spec.fov)),
      vertical_angle_(radians(spec.vertical_fov)),
      extent_(spec.height),
      cylinder_axis_across_(spec.cylinder_axis_across),
      cylinder_parallel_(spec.cylinder_parallel) {
    const Frame f = view_frame(spec.from, spec.at, spec.up);
    u_ = f.u, v_ = f.v, n_ = f.n;
    if (!spec.motion.empty()) {
        std::vector<Keyframe> keyframes;
        for (const CameraKeyframe& k : spec.motion)
            keyframes.push_back({k.time, world_from_camera(k.from, k.at, k.up)});
        motion_ = std::make_shared<const AnimatedTransform>(std::move(keyframes));
        // Rays are made in the camera's own frame, then placed by the motion.
        eye_ = {0, 0, 0};
        u_ = {1, 0, 0}, v_ = {0, 1, 0}, n_ = {0, 0, 1};
    }
    if (spec.left_handed) u_ = -u_;
    half_height_ =
        projection_ == Projection::perspective ? std::tan(radians(spec.fov) / 2) : spec.height / 2;
    half_width_ = half_height_ * aspect_;
}

namespace {

// The fisheye's point for film position (a, b), each in [-1/2, 1/2]: on the circle of radius
// 1 that the view's height spans at its rim.
Point2 fisheye_point(float a, float b, float aspect) { return {2 * a * aspect, 2 * b}; }

}  // namespace

bool Camera::sees(Point2 film) const {
    if (projection_ != Projection::fisheye) return true;
    const Point2 p = fisheye_point(film.x / width_ - 0.5f, 0.5f - film.y / height_, aspect_);
    return p.x * p.x + p.y * p.y <= 1;
}

// The wide projections' eye ray, from the eye (or beside it, looking parallel along a
// cylinder's axis), with a unit direction; a and b in [-1/2, 1/2] from left to right and from
// bottom to top. POV-Ray's camera types, as its documentation gives them.
Ray Camera::wide_ray(float a, float b) const {
    Point3 origin = eye_;
    Vector3 d;
    switch (projection_) {
        case Projection::fisheye: {
            // The angle from the axis is the distance from the centre times half the fov.
            const Point2 p = fisheye_point(a, b, aspect_);
            const float r = std::sqrt(p.x * p.x + p.y * p.y), theta = r * angle_ / 2;
            const float s = r > 0 ? std::sin(theta) / r : 0;
            d = s * p.x * u_ + s * p.y * v_ + std::cos(theta) * n_;
            break;
        }
        case Projection::ultra_wide_angle: {
            const float x = a * angle_, y = b * angle_ / aspect_;
            d = std::sin(x) * u_ + std::sin(y) * v_ + std::cos(x) * std::cos(y) * n_;
            break;
        }
        case Projection::panoramic: {
            // Half a turn from the left (-u) to the right; up the tangent of b half turns.
            const float x = (0.5f - a) * kPi;
            const float y = std::clamp(b * kPi, -0.4999f * kPi, 0.4999f * kPi);
            d = std::cos(x) * aspect_ * u_ + std::tan(y) * v_ + std::sin(x) * n_;
            break;
        }
        case Projection::cylindrical: {
            // Round the axis by the angle across; along it by the extent.
            const float turn = (cylinder_axis_across_ ? b : a) * angle_;
            const float along = (cylinder_axis_across_ ? a : b) * extent_;
            const Vector3 round = cylinder_axis_across_ ? v_ : u_;
            const Vector3 axis = cylinder_axis_across_ ? u_ : v_;
            d = std::sin(turn) * round + std::cos(turn) * n_;
            if (cylinder_parallel_)
                origin = origin + along * axis;
            else
                d = d + along * axis;
            break;
        }
        case Projection::spherical: {
            const float longitude = a * angle_, latitude = b * vertical_angle_;
            d = std::cos(latitude) * (std::sin(longitude) * u_ + std::cos(longitude) * n_) +
                std::sin(latitude) * v_;
            break;
        }
        case Projection::perspective:
        case Projection::orthographic:
            break;
    }
    return {origin, normalize(d)};
}

Point2 Camera::aperture_point(Point2 u) const {
    if (blades_ >= 3) return sample_regular_polygon(u, blades_, blade_rotation_);
    return sample_uniform_disk(u);
}

Ray Camera::generate_ray(Point2 film, Point2 lens, float time) const {
    return generate_ray_from_aperture(film, has_lens() ? aperture_point(lens) : Point2{0, 0}, time);
}

Ray Camera::generate_ray_from_aperture(Point2 film, Point2 aperture, float time) const {
    // Viewport to window: x from -1 (left) to 1 (right), y from 1 (top) to -1 (bottom).
    const float x = (2 * film.x / width_ - 1) * half_width_;
    const float y = (1 - 2 * film.y / height_) * half_height_;
    // The pinhole ray, its direction 1 along n (u and v are perpendicular to n); a wide
    // projection's of unit length, so that its plane of focus is a sphere round the eye.
    const bool orthographic = projection_ == Projection::orthographic;
    const bool wide = projection_ != Projection::perspective && !orthographic;
    const Ray pinhole = wide ? wide_ray(film.x / width_ - 0.5f, 0.5f - film.y / height_)
                             : Ray{orthographic ? eye_ + x * u_ + y * v_ : eye_,
                                   orthographic ? n_ : n_ + x * u_ + y * v_};
    const Point3 origin = pinhole.origin;
    const Vector3 direction = pinhole.direction;
    Ray ray;
    if (lens_radius_ > 0) {
        // From a point of the aperture to where the pinhole ray meets the plane of focus: at
        // focus_distance times its direction.
        const Point3 focus = origin + direction * focus_distance_;
        ray.origin = origin + (aperture.x * u_ + aperture.y * v_) * lens_radius_;
        ray.direction = normalize(focus - ray.origin);
    } else {
        ray = {origin, orthographic || wide ? direction : normalize(direction)};
    }
    ray.time = time;
    if (motion_) {
        const Transform world = motion_->at(time);
        ray.origin = world(ray.origin);
        ray.direction = normalize(world(ray.direction));
    }
    return ray;
}

std::optional<Camera::Connection> Camera::connect(Point3 p, Point2 lens, float time) const {
    if (projection_ != Projection::perspective) return std::nullopt;
    // In the camera's frame: the eye at the origin, u right, v up, n forward.
    Point3 q = p;
    if (motion_) q = motion_->at(time).inverse()(p);
    const Vector3 e = q - eye_;
    const Vector3 local{dot(e, u_), dot(e, v_), dot(e, n_)};
    Vector3 lens_point{0, 0, 0};
    if (lens_radius_ > 0) {
        const Point2 a = aperture_point(lens);
        lens_point = {a.x * lens_radius_, a.y * lens_radius_, 0};
    }
    const Vector3 d = local - lens_point;
    if (!(d.z > 0)) return std::nullopt;
    // Where the ray from the lens point through p meets the plane of focus (for a pinhole, any
    // plane): the pinhole ray through there gives the film position.
    const float focus = lens_radius_ > 0 ? focus_distance_ : 1;
    const Vector3 f = lens_point + d * (focus / d.z);
    const float x = f.x / focus, y = f.y / focus;  // on the window at distance 1
    Connection c;
    c.film = {(x / half_width_ + 1) * width_ / 2, (1 - y / half_height_) * height_ / 2};
    const Point3 lens_camera = eye_ + lens_point.x * u_ + lens_point.y * v_;
    c.lens = motion_ ? motion_->at(time)(lens_camera) : lens_camera;
    const Vector3 to_camera = c.lens - p;
    c.distance = length(to_camera);
    if (!(c.distance > 0)) return std::nullopt;
    c.to_camera = to_camera / c.distance;
    const float cos_theta = d.z / length(d);
    const float area = 4 * half_width_ * half_height_;
    c.importance = 1 / (area * cos_theta * cos_theta * cos_theta * c.distance * c.distance);
    return c;
}

}  // namespace glint
