// The working space's transfer functions with worked numbers, and encode as decode's inverse.
#include "glint/scene/working_space.h"

#include <gtest/gtest.h>

#include <cmath>

namespace glint {
namespace {

using Transfer = WorkingSpace::Transfer;

TEST(WorkingSpace, LinearLeavesValuesAsTheyAre) {
    const Color c{0.5f, -1, 7};
    EXPECT_EQ(decode({}, c), c);
    EXPECT_EQ(encode({}, c), c);
}

TEST(WorkingSpace, GammaWorkedNumbers) {
    const WorkingSpace g22{Transfer::gamma, 2.2f};
    // 0.5^2.2 = 0.21764; 0.21764^(1/2.2) = 0.5; 2^2.2 = 4.5948 past white.
    EXPECT_NEAR(decode(g22, Color::gray(0.5f)).r, 0.21764f, 1e-5f);
    EXPECT_NEAR(encode(g22, Color::gray(0.21764f)).g, 0.5f, 1e-5f);
    EXPECT_NEAR(decode(g22, Color::gray(2)).b, 4.5948f, 1e-4f);
}

TEST(WorkingSpace, SrgbWorkedNumbersAndItsPowerLawPastWhite) {
    const WorkingSpace srgb{Transfer::srgb, 1};
    // ((0.5 + 0.055) / 1.055)^2.4 = 0.21404; the linear toe: 0.02 / 12.92 = 0.001548.
    EXPECT_NEAR(decode(srgb, Color::gray(0.5f)).r, 0.21404f, 1e-5f);
    EXPECT_NEAR(decode(srgb, Color::gray(0.02f)).r, 0.001548f, 1e-6f);
    // 1.5 continues the curve: (1.555 / 1.055)^2.4 = 2.53716, and back.
    EXPECT_NEAR(decode(srgb, Color::gray(1.5f)).r, 2.53716f, 1e-4f);
    EXPECT_NEAR(encode(srgb, Color::gray(2.53716f)).r, 1.5f, 1e-5f);
}

TEST(WorkingSpace, EncodeInvertsDecodeAndNonPositiveValuesGiveZero) {
    for (const WorkingSpace space :
         {WorkingSpace{Transfer::gamma, 2.2f}, WorkingSpace{Transfer::gamma, 0.45f},
          WorkingSpace{Transfer::srgb, 1}}) {
        for (const float v : {0.001f, 0.04f, 0.3f, 0.9f, 1.0f, 3.0f}) {
            EXPECT_NEAR(encode(space, decode(space, Color::gray(v))).r, v, 2e-4f * (1 + v));
        }
        const Color zero = decode(space, Color{-0.5f, 0, std::nanf("")});
        EXPECT_EQ(zero, (Color{0, 0, 0}));
        EXPECT_EQ(encode(space, Color{-0.5f, 0, std::nanf("")}), (Color{0, 0, 0}));
    }
}

}  // namespace
}  // namespace glint
