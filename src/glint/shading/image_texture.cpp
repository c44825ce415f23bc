// Wrapping and filtering of image texture lookups.
#include "glint/shading/image_texture.h"

#include <algorithm>
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

Color texel(const Image& image, int i, int j, TextureWrap wrap) {
    return image.at(wrap_index(i, image.width, wrap), wrap_index(j, image.height, wrap));
}

// u and v already wrapped into [0, 1].
Color nearest(const Image& image, float u, float v, TextureWrap wrap) {
    return texel(image, int(std::floor(u * float(image.width))),
                 int(std::floor((1 - v) * float(image.height))), wrap);
}

Color bilinear(const Image& image, float u, float v, TextureWrap wrap) {
    // Continuous texel coordinates with texel (i, j)'s centre at (i + 1/2, j + 1/2), j from the
    // top.
    const float fx = u * float(image.width) - 0.5f, fy = (1 - v) * float(image.height) - 0.5f;
    const float x0 = std::floor(fx), y0 = std::floor(fy);
    const float tx = fx - x0, ty = fy - y0;
    const int i = int(x0), j = int(y0);
    const Color top = texel(image, i, j, wrap) * (1 - tx) + texel(image, i + 1, j, wrap) * tx;
    const Color bottom =
        texel(image, i, j + 1, wrap) * (1 - tx) + texel(image, i + 1, j + 1, wrap) * tx;
    return top * (1 - ty) + bottom * ty;
}

// The two axes of the footprint in texels of level 0, y down the image as rows go.
struct TexelAxes {
    float ax, ay, bx, by;
};
TexelAxes texel_axes(const Image& base, const UvFootprint& f) {
    const float w = float(base.width), h = float(base.height);
    return {f.dudx * w, -f.dvdx * h, f.dudy * w, -f.dvdy * h};
}

// Blends f(level) between the levels around lod, the coarsest level standing for any beyond.
template <class F>
Color between_levels(const MipMap& mip, float lod, F f) {
    const int last = mip.levels() - 1;
    if (!(lod > 0)) return f(0);  // also NaN
    if (lod >= float(last)) return f(last);
    const int l0 = int(lod);
    const float t = lod - float(l0);
    return f(l0) * (1 - t) + f(l0 + 1) * t;
}

Color trilinear(const MipMap& mip, float u, float v, const UvFootprint& footprint,
                TextureWrap wrap) {
    // OpenGL's scale factor: the longer of the two steps across the image, in texels.
    const TexelAxes a = texel_axes(mip.base(), footprint);
    const float rho = std::max(std::hypot(a.ax, a.ay), std::hypot(a.bx, a.by));
    return between_levels(mip, std::log2(rho),
                          [&](int level) { return bilinear(mip.level(level), u, v, wrap); });
}

// Longer footprints are widened to this ratio of axes, bounding the texels an ewa lookup reads.
constexpr float kMaxAnisotropy = 8;

// The Gaussian-weighted mean of the texels inside the ellipse round (u, v) whose conjugate
// semi-axes are (ax, ay) and (bx, by) texels of this level.
Color ewa_at(const Image& image, float u, float v, float ax, float ay, float bx, float by,
             TextureWrap wrap) {
    const float s = u * float(image.width) - 0.5f, t = (1 - v) * float(image.height) - 0.5f;
    // The ellipse A x^2 + B x y + C y^2 = F through the axes' ends, widened by a texel so that
    // it never falls between texel centres, then scaled to F = 1.
    float A = ay * ay + by * by + 1;
    float B = -2 * (ax * ay + bx * by);
    float C = ax * ax + bx * bx + 1;
    const float inverse_f = 1 / (A * C - B * B / 4);
    A *= inverse_f;
    B *= inverse_f;
    C *= inverse_f;
    // Its bounding box.
    const float det = 4 * A * C - B * B;
    const float half_width = 2 * std::sqrt(det * C) / det,
                half_height = 2 * std::sqrt(A * det) / det;
    const int s0 = int(std::ceil(s - half_width)), s1 = int(std::floor(s + half_width));
    const int t0 = int(std::ceil(t - half_height)), t1 = int(std::floor(t + half_height));
    constexpr float kAlpha = 2;  // the Gaussian's falloff, exp(-alpha r^2)
    const float edge = std::exp(-kAlpha);
    Color sum;
    float weights = 0;
    for (int j = t0; j <= t1; ++j) {
        const float dt = float(j) - t;
        for (int i = s0; i <= s1; ++i) {
            const float ds = float(i) - s;
            const float r2 = A * ds * ds + B * ds * dt + C * dt * dt;
            if (r2 >= 1) continue;
            const float w = std::exp(-kAlpha * r2) - edge;
            sum += texel(image, i, j, wrap) * w;
            weights += w;
        }
    }
    return weights > 0 ? sum * (1 / weights) : bilinear(image, u, v, wrap);
}

Color ewa(const MipMap& mip, float u, float v, const UvFootprint& footprint, TextureWrap wrap) {
    TexelAxes a = texel_axes(mip.base(), footprint);
    if (!std::isfinite(a.ax + a.ay + a.bx + a.by)) return bilinear(mip.base(), u, v, wrap);
    float major = std::hypot(a.ax, a.ay), minor = std::hypot(a.bx, a.by);
    if (minor > major) {
        std::swap(a.ax, a.bx);
        std::swap(a.ay, a.by);
        std::swap(major, minor);
    }
    if (major == 0) return bilinear(mip.base(), u, v, wrap);
    if (minor * kMaxAnisotropy < major) {  // widen the shorter axis (along its own direction)
        const float widen = major / (kMaxAnisotropy * std::max(minor, 1e-20f));
        if (minor > 0) {
            a.bx *= widen;
            a.by *= widen;
        } else {  // no shorter axis at all: the perpendicular of the longer one
            a.bx = -a.ay / kMaxAnisotropy;
            a.by = a.ax / kMaxAnisotropy;
        }
        minor = major / kMaxAnisotropy;
    }
    const float lod = std::log2(minor);
    const int last = mip.levels() - 1;
    // A footprint wider than the image: the image's mean, without visiting every texel.
    if (lod >= float(last)) return bilinear(mip.level(last), u, v, wrap);
    return between_levels(mip, lod, [&](int level) {
        const float scale = 1 / float(1 << level);
        return ewa_at(mip.level(level), u, v, a.ax * scale, a.ay * scale, a.bx * scale,
                      a.by * scale, wrap);
    });
}

}  // namespace

Color sample(const ImageTexture& texture, Point2 uv, const UvFootprint& footprint) {
    const MipMap& mip = *texture.image;
    const float u = wrap_coordinate(uv.x, texture.wrap);
    const float v = wrap_coordinate(uv.y, texture.wrap);
    switch (texture.filter) {
        case TextureFilter::nearest:
            return nearest(mip.base(), u, v, texture.wrap) * texture.scale;
        case TextureFilter::bilinear:
            return bilinear(mip.base(), u, v, texture.wrap) * texture.scale;
        case TextureFilter::trilinear:
            return trilinear(mip, u, v, footprint, texture.wrap) * texture.scale;
        case TextureFilter::ewa:
            return ewa(mip, u, v, footprint, texture.wrap) * texture.scale;
    }
    return {};
}

}  // namespace glint
