// A colour texture read from an image and painted on the surface's uv coordinates, with repeat
// or clamp wrapping, filtered at a point (nearest, bilinear) or over the footprint of the pixel
// that looks it up (trilinear mip-mapping, or an elliptical weighted average).
#pragma once

#include <memory>

#include "glint/geometry/surface_point.h"
#include "glint/math/color.h"
#include "glint/math/vector.h"
#include "glint/shading/mip_map.h"

namespace glint {

enum class TextureWrap { repeat, clamp };
// nearest and bilinear read the image itself at the point; trilinear (Williams 1983) blends
// bilinear lookups in the two mip-map levels whose texels are about as wide as the footprint's
// longer axis; ewa (Greene and Heckbert 1986) weighs the texels under the footprint's ellipse
// with a Gaussian, at the level where its shorter axis is about a texel.
enum class TextureFilter { nearest, bilinear, trilinear, ewa };

// Texel (i, j) (column i, row j from the top) covers u in [i, i + 1] / width and v in
// [height - 1 - j, height - j] / height: v = 0 is the image's bottom row, as in OpenGL and OBJ.
struct ImageTexture {
    std::shared_ptr<const MipMap> image;  // linear RGB; never null
    Color scale{1, 1, 1};                 // multiplies every texel (MTL Kd, glTF baseColorFactor)
    TextureWrap wrap = TextureWrap::repeat;
    TextureFilter filter = TextureFilter::trilinear;
};

// The filtered colour at uv. Texel centres sit at half-integer positions, so bilinear filtering
// blends the four texels around (u width - 1/2, (1 - v) height - 1/2). The footprint matters to
// trilinear and ewa only; with none they read as bilinear. NaN coordinates read as 0; any
// finite uv is safe. Allocates nothing.
Color sample(const ImageTexture& texture, Point2 uv, const UvFootprint& footprint = {});

}  // namespace glint
