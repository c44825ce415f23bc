// Noise textures: every pattern's values in [0, 1], its gradient against central differences,
// the scale as a change of units, the colour ramp, scalar maps and bump maps.
#include "glint/shading/noise_texture.h"

#include <gtest/gtest.h>

#include <cmath>

#include "glint/sampling/random.h"

namespace glint {
namespace {

constexpr NoisePattern kPatterns[] = {NoisePattern::fbm, NoisePattern::granite,
                                      NoisePattern::marble, NoisePattern::turbulence,
                                      NoisePattern::wood};

Point3 random_point(int i) {
    return {20 * random_float(i, 0, 0, 9) - 10, 20 * random_float(i, 0, 1, 9) - 10,
            20 * random_float(i, 0, 2, 9) - 10};
}

TEST(NoiseTexture, EveryPatternStaysInTheUnitInterval) {
    for (const NoisePattern pattern : kPatterns) {
        const NoiseSpec spec{pattern, 0.7f, 1.5f, 5};
        float low = 1, high = 0;
        for (int i = 0; i < 5000; ++i) {
            const float v = noise_value(spec, random_point(i));
            ASSERT_GE(v, 0);
            ASSERT_LE(v, 1);
            low = std::min(low, v), high = std::max(high, v);
        }
        EXPECT_GT(high - low, 0.2f) << int(pattern);  // and it varies
    }
}

TEST(NoiseTexture, ScaleIsTheSizeOfAFeature) {
    const NoiseSpec unit{NoisePattern::marble, 1, 1, 4}, large{NoisePattern::marble, 2.5f, 1, 4};
    for (int i = 0; i < 100; ++i) {
        const Point3 p = random_point(i);
        EXPECT_NEAR(noise_value(large, p), noise_value(unit, Point3{0, 0, 0} + to_vector(p) / 2.5f),
                    1e-6f);
    }
}

TEST(NoiseTexture, GradientsMatchCentralDifferences) {
    for (const NoisePattern pattern : kPatterns) {
        const NoiseSpec spec{pattern, 1.3f, 0.5f, 3};
        int close = 0;
        for (int i = 0; i < 200; ++i) {
            const Point3 p = random_point(i);
            const Vector3 g = noise_gradient(spec, p);
            const float h = 1e-3f;
            const Vector3 d{(noise_value(spec, p + Vector3{h, 0, 0}) -
                             noise_value(spec, p - Vector3{h, 0, 0})) /
                                (2 * h),
                            (noise_value(spec, p + Vector3{0, h, 0}) -
                             noise_value(spec, p - Vector3{0, h, 0})) /
                                (2 * h),
                            (noise_value(spec, p + Vector3{0, 0, h}) -
                             noise_value(spec, p - Vector3{0, 0, h})) /
                                (2 * h)};
            close += length(g - d) < 0.05f * (1 + length(d));
        }
        // Creases (turbulence's |noise| = 0, clamps, wood's ring edges) may differ at a few;
        // granite's fine turbulence has the most of them.
        EXPECT_GT(close, 180) << "pattern " << int(pattern);
    }
}

TEST(NoiseTexture, ColoursComeFromTheRampAndScalarsSpanLowToHigh) {
    const NoiseSpec spec{NoisePattern::fbm, 1, 1, 4};
    const NoiseTexture texture{spec, {{1, 0, 0}, {0, 0, 1}}};
    const NoiseScalar scalar{spec, 0.2f, 0.6f};
    for (int i = 0; i < 100; ++i) {
        const Point3 p = random_point(i);
        const float v = noise_value(spec, p);
        const Color c = evaluate(texture, p);
        EXPECT_NEAR(c.r, 1 - v, 1e-5f);
        EXPECT_NEAR(c.b, v, 1e-5f);
        EXPECT_NEAR(evaluate(scalar, p), 0.2f + 0.4f * v, 1e-6f);
    }
}

TEST(NoiseTexture, BumpsTiltTheNormalDownhillAndStrengthZeroLeavesIt) {
    const Normal3 n{0, 1, 0};
    BumpMap bump{{NoisePattern::fbm, 1, 1, 4}, 0};
    EXPECT_EQ(bumped(bump, n, {0.3f, 0.1f, 0.7f}), n);
    bump.strength = 0.2f;
    for (int i = 0; i < 100; ++i) {
        const Point3 p = random_point(i);
        const Vector3 g = noise_gradient(bump.spec, p);
        const Normal3 b = bumped(bump, n, p);
        EXPECT_NEAR(length(to_vector(b)), 1, 1e-5f);
        // Tilted away from the uphill direction within the tangent plane.
        const Vector3 uphill{g.x, 0, g.z};
        if (length(uphill) > 1e-3f) {
            EXPECT_LT(dot(to_vector(b), uphill), 0);
        }
    }
}

}  // namespace
}  // namespace glint
