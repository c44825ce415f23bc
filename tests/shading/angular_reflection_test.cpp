// Reflection that varies with the angle against worked numbers: the falloff blend, Fresnel's
// blend for glass, and the metallic colour from facing the viewer to grazing incidence.
#include "glint/shading/angular_reflection.h"

#include <gtest/gtest.h>

#include <cmath>

namespace glint {
namespace {

TEST(AngularReflection, FalloffBlendsFromFacingToGrazing) {
    // kr = 0.1 + (0.6 - 0.1) (1 - cos)^falloff.
    const AngularReflection a{0.1f, 1, false};
    EXPECT_FLOAT_EQ(reflect_at(a, 0.6f, 1, 1), 0.1f);
    EXPECT_FLOAT_EQ(reflect_at(a, 0.6f, 0, 1), 0.6f);
    EXPECT_FLOAT_EQ(reflect_at(a, 0.6f, 0.5f, 1), 0.35f);
    const AngularReflection squared{0.1f, 2, false};
    EXPECT_FLOAT_EQ(reflect_at(squared, 0.6f, 0.5f, 1), 0.1f + 0.5f * 0.25f);
}

TEST(AngularReflection, FresnelBlendsByTheReflectanceOfTheObjectsIndex) {
    // Glass of index 1.5 seen from air: ((1.5 - 1) / (1.5 + 1))^2 = 0.04 facing the viewer, all
    // at grazing incidence.
    const AngularReflection a{0, 1, true};
    EXPECT_NEAR(reflect_at(a, 1, 1, 1 / 1.5f), 0.04f, 1e-6f);
    EXPECT_NEAR(reflect_at(a, 1, 0, 1 / 1.5f), 1, 1e-6f);
    // From 0.2 to 0.8: 0.2 + 0.6 x 0.04.
    EXPECT_NEAR(reflect_at(AngularReflection{0.2f, 1, true}, 0.8f, 1, 1 / 1.5f), 0.224f, 1e-6f);
}

TEST(AngularReflection, AMetallicReflectionTakesTheColourFacingTheViewer) {
    const Color gold{1, 0.7f, 0.2f};
    // Facing the viewer POV-Ray's curve is 0.014567225 / 1.12^2 - 0.011612903 = 0.0000001:
    // the colour, all of it with metallic 1, half of it with 0.5.
    const Color facing = metallic_reflection(1, gold, 1);
    EXPECT_NEAR(facing.g, 0.7f, 1e-5f);
    EXPECT_NEAR(facing.b, 0.2f, 1e-5f);
    EXPECT_NEAR(metallic_reflection(0.5f, gold, 1).b, 0.6f, 1e-5f);
    // At grazing incidence the curve is 0.014567225 / 0.12^2 - 0.011612903 = 1: white.
    const Color grazing = metallic_reflection(1, gold, 0);
    EXPECT_NEAR(grazing.g, 1, 1e-5f);
    EXPECT_NEAR(grazing.b, 1, 1e-5f);
    // At 60 degrees (x = 2/3): 0.014567225 / 0.4533^2 - 0.011612903 = 0.059279.
    const float f = 0.014567225f / ((2 / 3.0f - 1.12f) * (2 / 3.0f - 1.12f)) - 0.011612903f;
    EXPECT_NEAR(metallic_reflection(1, gold, 0.5f).b, 1 + (1 - f) * (0.2f - 1), 1e-5f);
}

}  // namespace
}  // namespace glint
