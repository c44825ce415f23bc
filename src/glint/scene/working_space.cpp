// The working space's transfer functions, each channel on its own.
#include "glint/scene/working_space.h"

#include <cmath>

#include "glint/image/srgb.h"

namespace glint {

namespace {

using Transfer = WorkingSpace::Transfer;

float decode_one(const WorkingSpace& space, float v) {
    if (!(v > 0)) return 0;
    if (space.transfer == Transfer::gamma) return std::pow(v, space.gamma);
    return v > 1 ? std::pow((v + 0.055f) / 1.055f, 2.4f) : srgb_to_linear(v);
}

float encode_one(const WorkingSpace& space, float v) {
    if (!(v > 0)) return 0;
    if (space.transfer == Transfer::gamma) return std::pow(v, 1 / space.gamma);
    return v > 1 ? 1.055f * std::pow(v, 1 / 2.4f) - 0.055f : linear_to_srgb(v);
}

}  // namespace

Color decode(const WorkingSpace& space, Color c) {
    if (space.transfer == Transfer::linear) return c;
    return {decode_one(space, c.r), decode_one(space, c.g), decode_one(space, c.b)};
}

Color encode(const WorkingSpace& space, Color c) {
    if (space.transfer == Transfer::linear) return c;
    return {encode_one(space, c.r), encode_one(space, c.g), encode_one(space, c.b)};
}

}  // namespace glint
