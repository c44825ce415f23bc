// A primitive is a shape as acceleration structures see it: geometry plus the kinds of rays
// that may hit it (a per-primitive mask, as in Embree).
#pragma once

#include <cstdint>

#include "glint/geometry/shape.h"

namespace glint {

// Bits of Primitive::visibility and of a query's ray mask; a primitive is hit only by rays
// whose mask shares a bit with its visibility.
enum RayVisibility : std::uint32_t {
    kVisibleToCameraRays = 1u << 0,  // eye, reflected and refracted rays
    kVisibleToShadowRays = 1u << 1,  // shadow feelers: the primitive casts shadows
};

struct Primitive {
    Shape shape;
    std::uint32_t visibility = kVisibleToCameraRays | kVisibleToShadowRays;
};

}  // namespace glint
