#include "glint/shading/texture.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

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

TEST(Texture, AFaceOnACellBoundaryFallsIntoOneCell) {
    // A box's side at x = 1 (two cells of 0.5) whose points float rounded either way: all in
    // the cell above, 1e-6 of a cell being past the rounding.
    const CheckerTexture checker{kWhite, kBlack, 0.5f, CheckerSpace::solid};
    const float below = std::nextafter(1.0f, 0.0f), above = std::nextafter(1.0f, 2.0f);
    EXPECT_EQ(evaluate(checker, at({below, 0.1f, 0.1f})), kWhite);
    EXPECT_EQ(evaluate(checker, at({above, 0.1f, 0.1f})), kWhite);
    EXPECT_EQ(evaluate(checker, at({0.999f, 0.1f, 0.1f})), kBlack);  // a point inside the cell
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

// A pattern laid over the uv (POV-Ray's uv_mapping) reads (u, v, 0), not the point, and so
// does a pigment map laid over it, entries and all; both ask for the uv.
TEST(Texture, UvMappedPatternsAndMapsReadTheSurfacesUv) {
    auto ramp = std::make_shared<PatternTexture>();
    ramp->spec.kind = PatternKind::gradient;
    ramp->colors = {{0, kBlack}, {1, kWhite}};
    ramp->uv_mapping = true;
    const Color c = evaluate(Texture{ramp}, at({9, 9, 9}, {0.25f, 0.7f}));
    EXPECT_FLOAT_EQ(c.r, 0.25f);
    EXPECT_EQ(uv_needed(Texture{ramp}), Uv::compute);
    auto map = std::make_shared<PigmentMap>();
    map->spec.kind = PatternKind::gradient;
    map->spec.direction = {0, 1, 0};
    map->uv_mapping = true;
    auto in_space = std::make_shared<PatternTexture>(*ramp);
    in_space->uv_mapping = false;  // an entry sees the map's (u, v, 0)
    map->entries = {{0, Texture{kBlack}}, {1, Texture{in_space}}};
    // v = 0.5 picks half of the entry, whose gradient along x reads u = 0.25.
    EXPECT_FLOAT_EQ(evaluate(Texture{map}, at({9, 9, 9}, {0.25f, 0.5f})).r, 0.125f);
    EXPECT_EQ(uv_needed(Texture{map}), Uv::compute);
}

TEST(Texture, OnlyUvCheckersAndImagesNeedUv) {
    EXPECT_EQ(uv_needed(Color{1, 1, 1}), Uv::skip);
    EXPECT_EQ(uv_needed(CheckerTexture{kWhite, kBlack, 1, CheckerSpace::solid}), Uv::skip);
    EXPECT_EQ(uv_needed(CheckerTexture{kWhite, kBlack, 1, CheckerSpace::uv}), Uv::compute);
    EXPECT_EQ(uv_needed(ImageTexture{}), Uv::compute);
    EXPECT_EQ(uv_needed(NoiseTexture{}), Uv::skip);
}

TEST(Texture, MapsAndLayersNeedUvWhenAnyPartDoes) {
    auto map = std::make_shared<PigmentMap>();
    map->entries = {{0, kWhite}, {1, kBlack}};
    EXPECT_EQ(uv_needed(PigmentMapPtr(map)), Uv::skip);
    map->entries[1].texture = ImageTexture{};
    EXPECT_EQ(uv_needed(PigmentMapPtr(map)), Uv::compute);
    auto layered = std::make_shared<LayeredTexture>();
    layered->layers = {{kWhite, kBlack}, {PigmentMapPtr(map), kBlack}};
    EXPECT_EQ(uv_needed(LayeredTexturePtr(layered)), Uv::compute);
    layered->layers.pop_back();
    EXPECT_EQ(uv_needed(LayeredTexturePtr(layered)), Uv::skip);
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

// A red top layer with filter 1/2 and transmit 1/4 over an opaque one of diffuse weight 2 and
// ambient weight 4: the top covers by 1 - 1/2 - 1/4 = 1/4 and lets through
// 1/2 (0.5, 0, 0) + 1/4 = (0.5, 0.25, 0.25), so
//   C = 1/4 (0.5, 0, 0) + (0.5, 0.25, 0.25) (0.2, 0.4, 0.8) 2 = (0.325, 0.2, 0.4),
//   C_ambient = 1/4 (0.5, 0, 0) + (0.5, 0.25, 0.25) (0.2, 0.4, 0.8) 4 = (0.525, 0.4, 0.8).
// POV-Ray 3.6's opacity is 1 - (1/2 0.5 + 1/4) = 1/2 instead: C = (0.45, 0.2, 0.4).
TEST(Texture, LayersLetWhatLiesBelowThroughByTheirFilterAndTransmit) {
    auto layered = std::make_shared<LayeredTexture>();
    layered->layers = {{Color{0.5f, 0, 0}, Color{0.5f, 0.25f, 0}},
                       {Color{0.2f, 0.4f, 0.8f}, kBlack, 2, 4}};
    const Texture texture = LayeredTexturePtr(layered);
    const Color c = evaluate(texture, at({}));
    EXPECT_FLOAT_EQ(c.r, 0.325f);
    EXPECT_FLOAT_EQ(c.g, 0.2f);
    EXPECT_FLOAT_EQ(c.b, 0.4f);
    const Color ambient = evaluate_layers(*layered, at({})).ambient;
    EXPECT_FLOAT_EQ(ambient.r, 0.525f);
    EXPECT_FLOAT_EQ(ambient.g, 0.4f);
    EXPECT_FLOAT_EQ(ambient.b, 0.8f);
    layered->legacy_opacity = true;
    const Color legacy = evaluate(texture, at({}));
    EXPECT_FLOAT_EQ(legacy.r, 0.45f);
    EXPECT_FLOAT_EQ(legacy.g, 0.2f);
    EXPECT_FLOAT_EQ(legacy.b, 0.4f);
}

// Transmit varying over the surface, from 0 at x = 0 to 1 at x = 1 (a gradient through a colour
// map of the second source): a white top over a black bottom is 1 - x white. An opaque top hides
// the layers below it.
TEST(Texture, LayersFilterAndTransmitMayVaryOverTheSurface) {
    auto transmit = std::make_shared<PatternTexture>();
    transmit->spec.kind = PatternKind::gradient;
    transmit->colors = {{0, Color{0, 0, 0}}, {1, Color{0, 1, 0}}};
    auto layered = std::make_shared<LayeredTexture>();
    layered->layers = {{kWhite, PatternTexturePtr(transmit)}, {kBlack, kBlack}};
    const Texture texture = LayeredTexturePtr(layered);
    EXPECT_FLOAT_EQ(evaluate(texture, at({0.25f, 0, 0})).g, 0.75f);
    EXPECT_FLOAT_EQ(evaluate(texture, at({0.75f, 0, 0})).g, 0.25f);
    layered->layers = {{kWhite, kBlack}, {Color{1, 0, 0}, kBlack}};
    EXPECT_EQ(evaluate(texture, at({})), kWhite);
}

}  // namespace
}  // namespace glint
