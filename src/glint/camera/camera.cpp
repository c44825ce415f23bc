// The view-reference frame (n towards the target, u right, v up) and the eye ray through a film
// position, for both projections.
#include "glint/camera/camera.h"

#include <cmath>

#include "glint/math/constants.h"

namespace glint {

Camera::Camera(const CameraSpec& spec, int width, int height)
    : projection_(spec.projection),
      eye_(spec.from),
      width_(static_cast<float>(width)),
      height_(static_cast<float>(height)) {
    n_ = normalize(spec.at - spec.from);
    u_ = normalize(cross(n_, spec.up));  // right-handed: right = forward x up
    v_ = cross(u_, n_);
    half_height_ =
        projection_ == Projection::perspective ? std::tan(radians(spec.fov) / 2) : spec.height / 2;
    half_width_ = half_height_ * width_ / height_;
}

Ray Camera::generate_ray(Point2 film) const {
    // Viewport to window: x from -1 (left) to 1 (right), y from 1 (top) to -1 (bottom).
    const float x = (2 * film.x / width_ - 1) * half_width_;
    const float y = (1 - 2 * film.y / height_) * half_height_;
    if (projection_ == Projection::orthographic) return {eye_ + x * u_ + y * v_, n_};
    return {eye_, normalize(n_ + x * u_ + y * v_)};
}

}  // namespace glint
