// Where one sample of a pixel lands on the film and the eye ray it traces, from the sample's
// pixel, lens and shutter numbers: what the render loop and `glint explain` both start from.
#pragma once

#include <optional>

#include "glint/camera/camera.h"
#include "glint/math/ray.h"
#include "glint/render/pencil.h"
#include "glint/sampling/filter_sampling.h"
#include "glint/sampling/sampler.h"
#include "glint/scene/scene.h"

namespace glint {

// Whether a render draws its samples by filter importance sampling, each counting for its own
// pixel alone: under adaptive sampling, where a splatted pixel that stopped early would be
// pulled towards the colours of neighbours that took more samples. The one-pixel box splats
// into no other pixel, and needs none.
inline bool importance_samples_filter(const RenderSettings& settings) {
    return settings.adaptive && !is_one_pixel_box(filter_of(settings));
}

struct EyeSample {
    Point2 offset;  // the pixel dimension's numbers, [0,1)^2: the sample's place in the pixel
    Point2 film;    // on the film, in pixels
    float weight;   // the filter's weight under filter importance sampling; else 1
    Point2 lens;    // the lens dimension's numbers; (1/2, 1/2), none drawn, for a pinhole
    float time_u;   // the time dimension's number; 0, none drawn, when the shutter is closed
    float time;     // the moment; the shutter's opening when it does not move
    Ray ray;
    // The ray's pencil (pencil.h), when the render asks for one.
    std::optional<RayDifferential> pencil;
    const RayDifferential* pencil_or_null() const { return pencil ? &*pencil : nullptr; }
};

// The numbers a sample's eye ray is made from, drawn apart from the ray: the render loop draws a
// packet's numbers lane after lane, then its aperture points, then its rays, so that the
// processor overlaps the lanes' long chains of dependent instructions (hashes, a division, a
// square root) instead of waiting on each lane's in turn.
struct EyeNumbers {
    Point2 offset;          // the pixel dimension's
    Point2 lens;            // the lens dimension's; (1/2, 1/2), none drawn, for a pinhole
    float time_u;           // the time dimension's; 0, none drawn, when the shutter is closed
    Point2 aperture{0, 0};  // the lens's point (Camera::aperture_point), once worked out
};

inline EyeNumbers eye_numbers(const Camera& camera, const SampleStream& stream) {
    EyeNumbers n;
    n.offset = stream.get_2d(kPixelDimension);
    // A pinhole and a closed shutter draw no numbers for the lens and the time.
    n.lens = camera.has_lens() ? stream.get_2d(kLensDimension) : Point2{0.5f, 0.5f};
    n.time_u = camera.has_shutter() ? stream.get_1d(kTimeDimension) : 0;
    return n;
}

inline void find_aperture_point(const Camera& camera, EyeNumbers& n) {
    if (camera.has_lens()) n.aperture = camera.aperture_point(n.lens);
}

// The sample of numbers whose aperture point is worked out. With `filter`, the pixel's numbers
// are drawn through filter importance sampling, and the film position may lie in a
// neighbouring pixel or beyond the image's edge. A pencil_scale above 0 gives the ray its
// pencil, that fraction of the pixel's (eye_pencil_scale).
inline EyeSample eye_sample(const Camera& camera, const EyeNumbers& n, int x, int y,
                            const FilterSampling* filter = nullptr, float pencil_scale = 0) {
    EyeSample e;
    e.offset = n.offset;
    e.film = {float(x) + e.offset.x, float(y) + e.offset.y};
    e.weight = 1;
    if (filter) {
        const FilterSample f = filter->sample(e.offset);
        e.film = {float(x) + f.position.x, float(y) + f.position.y};
        e.weight = f.weight;
    }
    e.lens = n.lens;
    e.time_u = n.time_u;
    e.time = camera.has_shutter() ? camera.shutter_time(e.time_u) : camera.shutter_open();
    e.ray = camera.generate_ray_from_aperture(e.film, n.aperture, e.time);
    if (pencil_scale > 0)
        e.pencil = eye_pencil(camera, e.ray, e.film, e.lens, e.time, pencil_scale);
    return e;
}

// The same from the sample's stream, in one go.
inline EyeSample eye_sample(const Camera& camera, const SampleStream& stream, int x, int y,
                            const FilterSampling* filter = nullptr, float pencil_scale = 0) {
    EyeNumbers n = eye_numbers(camera, stream);
    find_aperture_point(camera, n);
    return eye_sample(camera, n, x, y, filter, pencil_scale);
}

}  // namespace glint
