#include "glint/shading/texture.h"

#include <gtest/gtest.h>

namespace glint {
namespace {

SurfacePoint at(Point3 p, Point2 uv = {}) {
    SurfacePoint sp;
    sp.p = p;
    sp.uv = uv;
    return sp;
}

const Color kWhite{1, 1, 1}, kBlack{0, 0, 0};

TEST(Texture, ConstantColour) { EXPECT_EQ(evaluate(Color{1, 2, 3}, at({})), (Color{1, 2, 3})); }

TEST(Texture, SolidCheckerAlternatesAcrossEveryAxisAndAcrossZero) {
    const CheckerTexture checker{kWhite, kBlack, 0.5f, CheckerSpace::solid};
    EXPECT_EQ(evaluate(checker, at({0.1f, 0.1f, 0.1f})), kWhite);
    EXPECT_EQ(evaluate(checker, at({0.6f, 0.1f, 0.1f})), kBlack);
    EXPECT_EQ(evaluate(checker, at({0.6f, 0.6f, 0.1f})), kWhite);
    EXPECT_EQ(evaluate(checker, at({0.6f, 0.6f, 0.6f})), kBlack);
    EXPECT_EQ(evaluate(checker, at({-0.1f, 0.1f, 0.1f})), kBlack);  // floor(-0.2) = -1
}

TEST(Texture, HugeCoordinatesOverTinySquaresStayDefined) {
    // 3e38 / 1e-30 overflows to infinity; the cell index must not go through an integer cast.
    const CheckerTexture checker{kWhite, kBlack, 1e-30f, CheckerSpace::solid};
    const Color c = evaluate(checker, at({3e38f, -3e38f, 1}));
    EXPECT_TRUE(c == kWhite || c == kBlack);
    EXPECT_EQ(
        evaluate(CheckerTexture{kWhite, kBlack, 1, CheckerSpace::solid}, at({1e30f, 0.5f, 0.5f})),
        kWhite);  // 1e30 is an even integer
}

TEST(Texture, UvCheckerUsesTextureCoordinates) {
    const CheckerTexture checker{kWhite, kBlack, 0.25f, CheckerSpace::uv};
    EXPECT_EQ(evaluate(checker, at({9, 9, 9}, {0.1f, 0.1f})), kWhite);
    EXPECT_EQ(evaluate(checker, at({9, 9, 9}, {0.3f, 0.1f})), kBlack);
    EXPECT_EQ(evaluate(checker, at({9, 9, 9}, {0.3f, 0.3f})), kWhite);
}

TEST(Texture, OnlyUvCheckersAndImagesNeedUv) {
    EXPECT_EQ(uv_needed(Color{1, 1, 1}), Uv::skip);
    EXPECT_EQ(uv_needed(CheckerTexture{kWhite, kBlack, 1, CheckerSpace::solid}), Uv::skip);
    EXPECT_EQ(uv_needed(CheckerTexture{kWhite, kBlack, 1, CheckerSpace::uv}), Uv::compute);
    EXPECT_EQ(uv_needed(ImageTexture{}), Uv::compute);
    EXPECT_EQ(uv_needed(NoiseTexture{}), Uv::skip);
}

// A pigment map: gradient x over [0, 2] (the map scaled by 2) blends red at 0 into, at 1, a
// solid checker scaled by 0.5 inside the map's space, so of unit cells in the scene's. At x = 1
// the pattern is 1/2: half red, half the checker there, whose cell (1, 0, 0) is odd: white.
TEST(Texture, PigmentMapBlendsItsEntriesTextures) {
    auto checker = std::make_shared<PatternTexture>();
    checker->spec.kind = PatternKind::checker;
    checker->colors = {{0, Color{0, 0, 0}}, {1, Color{1, 1, 1}}};
    checker->to_pattern = Transform::scale(2, 2, 2) * Transform::scale(0.5f, 0.5f, 0.5f);
    auto map = std::make_shared<PigmentMap>();
    map->spec.kind = PatternKind::gradient;
    map->entries = {{0, Color{1, 0, 0}}, {1, PatternTexturePtr(checker)}};
    map->to_pattern = Transform::scale(0.5f, 0.5f, 0.5f);
    const Texture texture = PigmentMapPtr(map);
    EXPECT_EQ(evaluate(texture, at({0, 0.25f, 0.25f})), (Color{1, 0, 0}));
    const Color half = evaluate(texture, at({1, 0.25f, 0.25f}));
    EXPECT_FLOAT_EQ(half.r, 1);
    EXPECT_FLOAT_EQ(half.g, 0.5f);
    EXPECT_FLOAT_EQ(half.b, 0.5f);
    // POV-Ray's average: the entries weighted by their values, 0 and 1: the checker alone.
    map->average = true;
    EXPECT_EQ(evaluate(texture, at({1, 0.25f, 0.25f})), (Color{1, 1, 1}));
}

}  // namespace
}  // namespace glint
