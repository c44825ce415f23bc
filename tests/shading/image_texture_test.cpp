// Image textures: bilinear lookups with worked numbers, wrap modes, nearest filtering, the
// orientation (v = 0 at the bottom row), the mip-map and the lookups filtered over a footprint.
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
    Image image(2, 2);
    image.at(0, 0) = {0, 0, 0};
    image.at(1, 0) = {1, 1, 0};
    image.at(0, 1) = {2, 0, 0};
    image.at(1, 1) = {3, 1, 0};
    return ImageTexture{std::make_shared<const MipMap>(std::move(image)), Color{1, 1, 1}, wrap,
                        filter};
}

// A checkerboard of single texels, black and white, size x size: its mean is 1/2 everywhere
// above level 0, and a point lookup at a texel centre gives 0 or 1.
ImageTexture checkerboard(int size, TextureFilter filter) {
    Image image(size, size);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) image.at(x, y) = Color::gray(float((x + y) % 2));
    return ImageTexture{std::make_shared<const MipMap>(std::move(image)), Color{1, 1, 1},
                        TextureWrap::repeat, filter};
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

TEST(ImageTexture, AbsurdCoordinatesAndFootprintsStayDefined) {
    constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
    const float values[] = {kNaN, kInfinity, -kInfinity, 3e38f, -3e38f, -1e-30f, 0, 1.0f};
    for (const TextureWrap wrap : {TextureWrap::repeat, TextureWrap::clamp}) {
        for (const TextureFilter filter : {TextureFilter::bilinear, TextureFilter::nearest,
                                           TextureFilter::trilinear, TextureFilter::ewa}) {
            const ImageTexture t = two_by_two(wrap, filter);
            for (const float x : values)
                for (const float d : values) {
                    const Color c = sample(t, {x, x}, {d, 0, 0, d});
                    EXPECT_TRUE(is_finite(c));
                    EXPECT_GE(c.r, 0);
                    EXPECT_LE(c.r, 3);
                }
        }
    }
}

TEST(MipMap, HalvesByTwoByTwoMeansDownToOneTexel) {
    Image image(3, 2);  // rows (0 1 2) over (3 4 5)
    for (int i = 0; i < 6; ++i) image.at(i % 3, i / 3) = Color::gray(float(i));
    const MipMap mip(image);
    ASSERT_EQ(mip.levels(), 3);  // 3x2, 2x1, 1x1
    EXPECT_EQ(mip.level(1).width, 2);
    EXPECT_EQ(mip.level(1).height, 1);
    EXPECT_FLOAT_EQ(mip.level(1).at(0, 0).r, (0 + 1 + 3 + 4) / 4.0f);
    // The odd column repeats: (2 + 2 + 5 + 5) / 4.
    EXPECT_FLOAT_EQ(mip.level(1).at(1, 0).r, 3.5f);
    EXPECT_FLOAT_EQ(mip.level(2).at(0, 0).r, (2 + 3.5f) / 2);
}

TEST(ImageTexture, TrilinearPicksTheLevelWhoseTexelsMatchTheFootprint) {
    const ImageTexture t = checkerboard(64, TextureFilter::trilinear);
    const Point2 centre{(10 + 0.5f) / 64, 1 - (20 + 0.5f) / 64};  // texel (10, 20): black
    // No footprint, or one under a texel wide: the texel itself.
    EXPECT_FLOAT_EQ(sample(t, centre).r, 0);
    EXPECT_FLOAT_EQ(sample(t, centre, {0.5f / 64, 0, 0, 0.5f / 64}).r, 0);
    // Two texels a pixel or more: level 1 and beyond, where the checks average to 1/2.
    EXPECT_FLOAT_EQ(sample(t, centre, {2.0f / 64, 0, 0, 2.0f / 64}).r, 0.5f);
    // Half way (in log2) between levels 0 and 1: the mean of the two lookups.
    const float sqrt2 = std::sqrt(2.0f);
    EXPECT_NEAR(sample(t, centre, {sqrt2 / 64, 0, 0, sqrt2 / 64}).r, 0.25f, 1e-5f);
    // The longer axis decides.
    EXPECT_FLOAT_EQ(sample(t, centre, {0, 4.0f / 64, 0.1f / 64, 0}).r, 0.5f);
}

TEST(ImageTexture, EwaAveragesUnderTheEllipseAtItsShorterAxis) {
    const ImageTexture t = checkerboard(64, TextureFilter::ewa);
    const Point2 centre{(10 + 0.5f) / 64, 1 - (20 + 0.5f) / 64};
    // A footprint of four texels each way: close to the mean 1/2 already at level 0.
    EXPECT_NEAR(sample(t, centre, {4.0f / 64, 0, 0, 4.0f / 64}).r, 0.5f, 0.02f);
    // Long and thin along u (16 texels by 1): the shorter axis keeps it at level 0, and it still
    // averages the checks along its length. A trilinear lookup of the same footprint picks the
    // level of the longer axis and blurs across v as much.
    const UvFootprint thin{16.0f / 64, 0, 0, 1.0f / 64};
    EXPECT_NEAR(sample(t, centre, thin).r, 0.5f, 0.05f);
    // On a texture of stripes across v, the thin footprint keeps the stripe it lies on.
    Image stripes(64, 64);
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) stripes.at(x, y) = Color::gray(float((y / 4) % 2));
    auto mip = std::make_shared<const MipMap>(std::move(stripes));
    const Point2 on_stripe{0.5f, 1 - (22 + 0.5f) / 64};  // row 22, inside white stripe 5
    const Color ewa =
        sample({mip, {1, 1, 1}, TextureWrap::repeat, TextureFilter::ewa}, on_stripe, thin);
    const Color trilinear =
        sample({mip, {1, 1, 1}, TextureWrap::repeat, TextureFilter::trilinear}, on_stripe, thin);
    EXPECT_GT(ewa.r, 0.95f);
    EXPECT_LT(trilinear.r, 0.8f);
}

TEST(ImageTexture, AFootprintWiderThanTheImageGivesItsMean) {
    for (const TextureFilter filter : {TextureFilter::trilinear, TextureFilter::ewa}) {
        const ImageTexture t = checkerboard(16, filter);
        EXPECT_FLOAT_EQ(sample(t, {0.3f, 0.7f}, {50, 0, 0, 50}).r, 0.5f);
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
