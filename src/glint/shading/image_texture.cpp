// Wrapping and filtering of image texture lookups.
#include "glint/shading/image_texture.h"

#include <cmath>

namespace glint {

namespace {

// Reduces a coordinate to [0, 1] before it is scaled to texels, so that the float-to-int casts
// below are always in range; NaN and infinities become 0.
float wrap_coordinate(float x, TextureWrap wrap) {
    if (!std::isfinite(x)) return 0;
    if (wrap == TextureWrap::clamp) return x < 0 ? 0 : x > 1 ? 1 : x;
    return x - std::floor(x);  // in [0, 1]; 1 only by rounding of tiny negatives
}

// A texel index wrapped into [0, size).
int wrap_index(int i, int size, TextureWrap wrap) {
    if (wrap == TextureWrap::clamp) return i < 0 ? 0 : i >= size ? size - 1 : i;
    i %= size;
    return i < 0 ? i + size : i;
}

}  // namespace

Color sample(const ImageTexture& texture, Point2 uv) {
    const Image& image = *texture.image;
    const float u = wrap_coordinate(uv.x, texture.wrap);
    const float v = wrap_coordinate(uv.y, texture.wrap);
    // Continuous texel coordinates with texel (i, j)'s centre at (i + 1/2, j + 1/2), j from the
    // top.
    const float x = u * float(image.width);
    const float y = (1 - v) * float(image.height);
    if (texture.filter == TextureFilter::nearest) {
        const int i = wrap_index(int(std::floor(x)), image.width, texture.wrap);
        const int j = wrap_index(int(std::floor(y)), image.height, texture.wrap);
        return image.at(i, j) * texture.scale;
    }
    const float fx = x - 0.5f, fy = y - 0.5f;
    const float x0 = std::floor(fx), y0 = std::floor(fy);
    const float tx = fx - x0, ty = fy - y0;
    const int i0 = int(x0), j0 = int(y0);
    const int i1 = wrap_index(i0 + 1, image.width, texture.wrap);
    const int j1 = wrap_index(j0 + 1, image.height, texture.wrap);
    const int i = wrap_index(i0, image.width, texture.wrap);
    const int j = wrap_index(j0, image.height, texture.wrap);
    const Color top = image.at(i, j) * (1 - tx) + image.at(i1, j) * tx;
    const Color bottom = image.at(i, j1) * (1 - tx) + image.at(i1, j1) * tx;
    return (top * (1 - ty) + bottom * ty) * texture.scale;
}

}  // namespace glint
