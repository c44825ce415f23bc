// The space a scene's colour arithmetic is done in: linear light, glint's own; or values encoded
// by a gamma or by sRGB's curve, as POV-Ray's scenes do theirs (in the space of their
// assumed_gamma). The film holds the working space's values; the image is decoded from them.
#pragma once

#include "glint/math/color.h"

namespace glint {

struct WorkingSpace {
    enum class Transfer { linear, gamma, srgb } transfer = Transfer::linear;
    float gamma = 1;  // with Transfer::gamma: v^gamma, gamma > 0
};

// Linear light from the working space's values: v^gamma, or sRGB's curve, continued above 1 by
// its power law so that highlights past white keep their brightness. Non-positive values (and
// NaN) give 0.
Color decode(const WorkingSpace& space, Color c);

// The inverse of decode: the working space's values of linear light (images, which glint reads
// as linear, encoded for a scene that works on encoded values).
Color encode(const WorkingSpace& space, Color c);

}  // namespace glint
