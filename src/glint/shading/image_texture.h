// A colour texture read from an image and painted on the surface's uv coordinates, with repeat
// or clamp wrapping and bilinear (or nearest) filtering.
#pragma once

#include <memory>

#include "glint/image/image.h"
#include "glint/math/color.h"
#include "glint/math/vector.h"

namespace glint {

enum class TextureWrap { repeat, clamp };
enum class TextureFilter { bilinear, nearest };

// Texel (i, j) (column i, row j from the top) covers u in [i, i + 1] / width and v in
// [height - 1 - j, height - j] / height: v = 0 is the image's bottom row, as in OpenGL and OBJ.
struct ImageTexture {
    std::shared_ptr<const Image> image;  // linear RGB; never null, never empty
    Color scale{1, 1, 1};                // multiplies every texel (MTL Kd, glTF baseColorFactor)
    TextureWrap wrap = TextureWrap::repeat;
    TextureFilter filter = TextureFilter::bilinear;
};

// The filtered colour at uv. Texel centres sit at half-integer positions, so bilinear filtering
// blends the four texels around (u width - 1/2, (1 - v) height - 1/2). NaN coordinates read as 0;
// any finite uv is safe. Allocates nothing.
Color sample(const ImageTexture& texture, Point2 uv);

}  // namespace glint
