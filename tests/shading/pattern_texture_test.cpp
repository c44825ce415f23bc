// Colour maps as POV-Ray reads them, and a pattern texture placed by its transform.
#include "glint/shading/pattern_texture.h"

#include <gtest/gtest.h>

#include <cmath>

namespace glint {
namespace {

// pigment { gradient x color_map { [0.2 rgb 0.1] [0.5 rgb 0.9] [0.5 rgb 0.2] [0.8 rgb 0.6] }
// scale 3 } at the points round the unit circle at height 0.3, as POV-Ray 3.7 evaluates it.
TEST(PatternTexture, ColourMapsAndPlacementGivePovRaysColours) {
    PatternTexture t;
    t.colors = {{0.2f, Color::gray(0.1f)},
                {0.5f, Color::gray(0.9f)},
                {0.5f, Color::gray(0.2f)},
                {0.8f, Color::gray(0.6f)}};
    t.to_pattern = Transform::scale(3, 3, 3).inverse();
    const float povray[8] = {0.4511f, 0.1293f, 0.6000f, 0.5226f,
                             0.4244f, 0.5853f, 0.1000f, 0.2548f};
    for (int i = 0; i < 8; ++i) {
        const double a = i * std::acos(-1.0) / 4 + 0.1;
        const Point3 p{float(std::cos(a)), 0.3f, float(std::sin(a))};
        EXPECT_NEAR(evaluate(t, p).r, povray[i], 2e-4) << i;
    }
}

TEST(PatternTexture, ColourAtIsLinearBetweenStopsAndHeldBeyond) {
    const std::vector<ColorStop> map{{0.25f, Color{1, 0, 0}}, {0.75f, Color{0, 0, 1}}};
    EXPECT_EQ(color_at(map, 0), (Color{1, 0, 0}));
    EXPECT_EQ(color_at(map, 1), (Color{0, 0, 1}));
    EXPECT_EQ(color_at(map, 0.5f), (Color{0.5f, 0, 0.5f}));
    EXPECT_EQ(color_at({{0.5f, Color{0, 1, 0}}}, 0.9f), (Color{0, 1, 0}));
    // Two stops at one place: a sharp edge, the later one from there on.
    const std::vector<ColorStop> edge{
        {0, Color{0, 0, 0}}, {0.5f, Color{1, 1, 1}}, {0.5f, Color{0, 0, 0}}, {1, Color{1, 0, 0}}};
    EXPECT_EQ(color_at(edge, 0.5f), (Color{0, 0, 0}));
    EXPECT_NEAR(color_at(edge, 0.4999f).r, 1, 1e-3);
}

}  // namespace
}  // namespace glint
