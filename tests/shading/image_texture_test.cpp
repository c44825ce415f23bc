// Image textures: bilinear lookups with worked numbers, wrap modes, nearest filtering and the
// orientation (v = 0 at the bottom row).
#include "glint/shading/image_texture.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "glint/math/interval.h"
#include "glint/shading/texture.h"

namespace glint {
namespace {

// 2x2, rows from the top: (0 1) over (2 3) in the red channel; green marks the column.
ImageTexture two_by_two(TextureWrap wrap = TextureWrap::repeat,
                        TextureFilter filter = TextureFilter::bilinear) {
    auto image = std::make_shared<Image>(2, 2);
    image->at(0, 0) = {0, 0, 0};
    image->at(1, 0) = {1, 1, 0};
    image->at(0, 1) = {2, 0, 0};
    image->at(1, 1) = {3, 1, 0};
    return ImageTexture{image, Color{1, 1, 1}, wrap, filter};
}

TEST(ImageTexture, TexelCentresGiveTheTexelsThemselves) {
    const ImageTexture t = two_by_two();
    // Texel (i, j) is centred at u = (i + 0.5) / 2, v = 1 - (j + 0.5) / 2.
    EXPECT_EQ(sample(t, {0.25f, 0.75f}).r, 0);  // top left
    EXPECT_EQ(sample(t, {0.75f, 0.75f}).r, 1);  // top right
    EXPECT_EQ(sample(t, {0.25f, 0.25f}).r, 2);  // bottom left: v = 0 is the bottom row
    EXPECT_EQ(sample(t, {0.75f, 0.25f}).r, 3);
}

TEST(ImageTexture, BilinearWorkedExample) {
    const ImageTexture t = two_by_two(TextureWrap::clamp);
    // u = 0.5, v = 0.5: x = 1 - 0.5 = 0.5, y = 0.5 between all four centres: (0+1+2+3)/4 = 1.5.
    EXPECT_FLOAT_EQ(sample(t, {0.5f, 0.5f}).r, 1.5f);
    // u = 0.375, v = 0.625: x = 0.75 - 0.5 = 0.25, y = 0.75 - 0.5 = 0.25 from the top left centre.
    // top = 0.75 * 0 + 0.25 * 1 = 0.25, bottom = 0.75 * 2 + 0.25 * 3 = 2.25,
    // value = 0.75 * 0.25 + 0.25 * 2.25 = 0.75.
    EXPECT_FLOAT_EQ(sample(t, {0.375f, 0.625f}).r, 0.75f);
    EXPECT_FLOAT_EQ(sample(t, {0.375f, 0.625f}).g, 0.25f);
}

TEST(ImageTexture, RepeatWrapsAroundTheEdgesAndClampStops) {
    // At u = 0 the lookup sits halfway between the last column and the first.
    const ImageTexture repeat = two_by_two(TextureWrap::repeat);
    EXPECT_FLOAT_EQ(sample(repeat, {0.0f, 0.75f}).r, 0.5f);  // (0 + 1) / 2 on the top row
    const ImageTexture clamp = two_by_two(TextureWrap::clamp);
    EXPECT_FLOAT_EQ(sample(clamp, {0.0f, 0.75f}).r, 0.0f);
    // Whole periods away gives the same under repeat; clamp holds the edge texel.
    EXPECT_FLOAT_EQ(sample(repeat, {3.375f, -1.375f}).r, sample(repeat, {0.375f, 0.625f}).r);
    EXPECT_FLOAT_EQ(sample(clamp, {5.0f, -3.0f}).r, 3);
    EXPECT_FLOAT_EQ(sample(clamp, {-5.0f, 7.0f}).r, 0);
}

TEST(ImageTexture, NearestPicksTheTexelUnderTheCoordinate) {
    const ImageTexture t = two_by_two(TextureWrap::repeat, TextureFilter::nearest);
    EXPECT_EQ(sample(t, {0.49f, 0.51f}).r, 0);
    EXPECT_EQ(sample(t, {0.51f, 0.51f}).r, 1);
    EXPECT_EQ(sample(t, {0.49f, 0.49f}).r, 2);
    EXPECT_EQ(sample(t, {0.99f, 0.01f}).r, 3);
}

TEST(ImageTexture, ScaleMultipliesEveryTexel) {
    ImageTexture t = two_by_two();
    t.scale = {2, 0.5f, 1};
    EXPECT_EQ(sample(t, {0.75f, 0.25f}), (Color{6, 0.5f, 0}));
}

TEST(ImageTexture, AbsurdCoordinatesStayDefined) {
    for (const TextureWrap wrap : {TextureWrap::repeat, TextureWrap::clamp}) {
        for (const TextureFilter filter : {TextureFilter::bilinear, TextureFilter::nearest}) {
            const ImageTexture t = two_by_two(wrap, filter);
            for (const float x : {std::numeric_limits<float>::quiet_NaN(), kInfinity, -kInfinity,
                                  3e38f, -3e38f, -1e-30f, 1.0f}) {
                const Color c = sample(t, {x, x});
                EXPECT_TRUE(is_finite(c));
                EXPECT_GE(c.r, 0);
                EXPECT_LE(c.r, 3);
            }
        }
    }
}

TEST(ImageTexture, EvaluatesThroughTheTextureVariant) {
    const Texture texture = two_by_two();
    SurfacePoint sp;
    sp.uv = {0.75f, 0.25f};
    EXPECT_EQ(evaluate(texture, sp).r, 3);
}

}  // namespace
}  // namespace glint
