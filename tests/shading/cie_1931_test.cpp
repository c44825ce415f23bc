#include "glint/shading/cie_1931.h"

#include <gtest/gtest.h>

#include <cmath>

namespace glint {
namespace {

TEST(Cie1931, GivesTheTableAtItsWavelengths) {
    const Xyz at555 = cie_1931(555);
    EXPECT_FLOAT_EQ(at555.x, 0.5120501f);
    EXPECT_FLOAT_EQ(at555.y, 1.0f);  // y-bar peaks at 1 at 555 nm
    EXPECT_FLOAT_EQ(at555.z, 0.005749999f);
    EXPECT_FLOAT_EQ(cie_1931(360).x, 0.0001299f);
    EXPECT_FLOAT_EQ(cie_1931(830).y, 0.00000045181f);
    EXPECT_FLOAT_EQ(cie_1931(830).z, 0.0f);
    EXPECT_FLOAT_EQ(cie_1931(445).z, 1.7826f);  // z-bar's peak
}

TEST(Cie1931, InterpolatesLinearlyBetweenEntries) {
    // 557.5 nm is halfway between 555 and 560 nm: the mean of the two entries.
    const Xyz mid = cie_1931(557.5f);
    EXPECT_NEAR(mid.x, (0.5120501f + 0.5945f) / 2, 1e-6);
    EXPECT_NEAR(mid.y, (1.0f + 0.995f) / 2, 1e-6);
    EXPECT_NEAR(mid.z, (0.005749999f + 0.0039f) / 2, 1e-6);
    // A quarter of the way from 600 to 605 nm.
    EXPECT_NEAR(cie_1931(601.25f).y, 0.631f + 0.25f * (0.5668f - 0.631f), 1e-6);
}

TEST(Cie1931, IsZeroOutsideItsRange) {
    for (float lambda : {0.0f, 359.9f, 830.1f, 1000.0f, NAN, INFINITY}) {
        const Xyz v = cie_1931(lambda);
        EXPECT_EQ(v.x, 0) << lambda;
        EXPECT_EQ(v.y, 0) << lambda;
        EXPECT_EQ(v.z, 0) << lambda;
    }
}

TEST(Cie1931, EqualEnergyWhiteHasChromaticityOneThird) {
    // The three functions are normalised to equal areas (illuminant E at x = y = 1/3), and the
    // area of y-bar is about 106.86 nm: a check that no entry of the table is garbled.
    double x = 0, y = 0, z = 0;
    for (const Xyz& v : cie_1931_table()) {
        x += v.x;
        y += v.y;
        z += v.z;
    }
    EXPECT_NEAR(5 * y, 106.86, 0.01);
    EXPECT_NEAR(x / (x + y + z), 1.0 / 3, 2e-4);
    EXPECT_NEAR(y / (x + y + z), 1.0 / 3, 2e-4);
}

}  // namespace
}  // namespace glint
