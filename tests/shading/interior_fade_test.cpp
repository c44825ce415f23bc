// Interior fade against worked numbers: Beer-Lambert's law and POV-Ray's power law, a colour
// that passes unfaded, and the checks every scene reader shares.
#include "glint/shading/interior_fade.h"

#include <gtest/gtest.h>

#include <cmath>

#include "glint/math/interval.h"

namespace glint::interior_fade_test {
namespace {

void expect_near(Color a, Color b, float tol = 1e-6f) {
    EXPECT_NEAR(a.r, b.r, tol);
    EXPECT_NEAR(a.g, b.g, tol);
    EXPECT_NEAR(a.b, b.b, tol);
}

TEST(InteriorFade, NoDistanceFadesNothing) {
    expect_near(fade_over(InteriorFade{}, 100), Color{1, 1, 1});
}

TEST(InteriorFade, ExponentialFadeIsBeerLambertOfTheColoursComplement) {
    // Colour (0.5, 1, 0) over 3 units of a fade distance 2: exp(-(1 - c) 1.5).
    const InteriorFade fade{2, InteriorFade::kExponential, {0.5f, 1, 0}};
    expect_near(fade_over(fade, 3), Color{std::exp(-0.75f), 1, std::exp(-1.5f)});
    // Twice the distance, the square: the law of a medium that absorbs.
    const Color once = fade_over(fade, 1.5f), twice = fade_over(fade, 3);
    expect_near(once * once, twice);
    // An endless way leaves only what the colour lets through whole.
    expect_near(fade_over(fade, kInfinity), Color{0, 1, 0});
}

TEST(InteriorFade, APowerHalvesTheFadingPartAtTheFadeDistance) {
    // c + (1 - c) / (1 + (d / D)^p): at d = D half of 1 - c is left, at d = 2D with p = 2 a
    // fifth.
    const InteriorFade fade{2, 2, {0.5f, 1, 0}};
    expect_near(fade_over(fade, 2), Color{0.75f, 1, 0.5f});
    expect_near(fade_over(fade, 4), Color{0.6f, 1, 0.2f});
    expect_near(fade_over(fade, kInfinity), Color{0.5f, 1, 0});
    // POV-Ray's power 0 unless given: half of the fading part, whatever the distance.
    expect_near(fade_over(InteriorFade{2, 0, {}}, 7), Color::gray(0.5f));
}

TEST(InteriorFade, PowersFromAThousandOnAreExponential) {
    const InteriorFade fade{1, 5000, {}};
    expect_near(fade_over(fade, 1), Color::gray(std::exp(-1.0f)));
}

TEST(InteriorFade, DescribesNumbersNoSceneMayGive) {
    EXPECT_EQ(describe_problem(InteriorFade{1, 2, {0.5f, 0.5f, 0.5f}}), "");
    EXPECT_EQ(describe_problem(InteriorFade{-1, 2, {}}), "fade distance must be finite and >= 0");
    EXPECT_EQ(describe_problem(InteriorFade{1, -2, {}}), "fade power must be finite and >= 0");
    EXPECT_EQ(describe_problem(InteriorFade{1, 2, {1.5f, 0, 0}}),
              "fade colour's channels must be in [0, 1]");
    EXPECT_EQ(describe_problem(InteriorFade{kInfinity, 2, {}}),
              "fade distance must be finite and >= 0");
}

}  // namespace
}  // namespace glint::interior_fade_test
