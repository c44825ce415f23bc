// What rays that leave the scene see, and what lights the scene from all round for the
// physically based integrators: one colour (the scene's background), or an image wrapped round
// the scene in latitude and longitude, drawn from by brightness.
#pragma once

#include <memory>
#include <optional>

#include "glint/image/image.h"
#include "glint/math/color.h"
#include "glint/math/vector.h"
#include "glint/sampling/distribution_2d.h"

namespace glint {

// An equirectangular image: its top row is straight up (+y), its bottom row straight down, and
// its middle column the direction +z, where a camera looks by default; -x, on that camera's
// right, lies a quarter of the image to the right of the middle. Turned about +y by
// `rotation`.
struct SkyImage {
    std::shared_ptr<const Image> image;  // linear RGB, finite and non-negative; never empty
    float rotation = 0;                  // radians, anticlockwise seen from above
    Color scale{1, 1, 1};                // multiplies every pixel
};

// The direction (unit) that the point uv of an equirectangular image shows, before rotation:
// what a sky is baked from.
Vector3 sky_image_direction(Point2 uv);

class Sky {
public:
    Sky() = default;  // black
    explicit Sky(Color uniform);
    explicit Sky(const SkyImage& image);

    // The radiance that arrives travelling along -w, from the sky in the direction w (of any
    // length).
    // The image is filtered bilinearly, wrapping round in longitude.
    Color radiance(Vector3 w) const;
    // A direction towards the sky, drawn with a density per steradian roughly proportional to
    // its radiance (uniform for one colour), written to *pdf; 0 when none could be drawn.
    Vector3 sample(Point2 u, float* pdf) const;
    float pdf(Vector3 w) const;  // w of any length
    // The radiance averaged over all directions: (1 / 4 pi) times its integral.
    Color mean_radiance() const { return mean_; }
    bool is_black() const { return glint::is_black(mean_); }

private:
    Vector3 to_image(Vector3 w) const;    // world direction to the image's frame
    Vector3 from_image(Vector3 w) const;  // and back

    Color mean_;  // the colour of a uniform sky
    std::optional<SkyImage> image_;
    float cos_rotation_ = 1, sin_rotation_ = 0;
    // Over the image's (u, v) square, by the brightest of each pixel and its neighbours (what
    // the bilinear filter can reach) times sin(theta): never zero where the radiance is not.
    std::shared_ptr<const Distribution2D> distribution_;
};

}  // namespace glint
