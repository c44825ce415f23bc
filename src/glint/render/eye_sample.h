// Where one sample of a pixel lands on the film and the eye ray it traces, from the sample's
// pixel, lens and shutter numbers: what the render loop and `glint explain` both start from.
#pragma once

#include "glint/camera/camera.h"
#include "glint/math/ray.h"
#include "glint/sampling/sampler.h"

namespace glint {

struct EyeSample {
    Point2 offset;  // the sample's place in the pixel, [0,1)^2: the pixel dimension's numbers
    Point2 film;    // on the film, in pixels
    Point2 lens;    // the lens dimension's numbers; (1/2, 1/2), none drawn, for a pinhole
    float time_u;   // the time dimension's number; 0, none drawn, when the shutter is closed
    float time;     // the moment; the shutter's opening when it does not move
    Ray ray;
};

inline EyeSample eye_sample(const Camera& camera, const SampleStream& stream, int x, int y) {
    EyeSample e;
    e.offset = stream.get_2d(kPixelDimension);
    e.film = {float(x) + e.offset.x, float(y) + e.offset.y};
    // A pinhole and a closed shutter draw no numbers for the lens and the time.
    e.lens = camera.has_lens() ? stream.get_2d(kLensDimension) : Point2{0.5f, 0.5f};
    e.time_u = 0;
    e.time = camera.shutter_open();
    if (camera.has_shutter()) {
        e.time_u = stream.get_1d(kTimeDimension);
        e.time = camera.shutter_time(e.time_u);
    }
    e.ray = camera.generate_ray(e.film, e.lens, e.time);
    return e;
}

}  // namespace glint
