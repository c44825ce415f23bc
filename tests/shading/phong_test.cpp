#include "glint/shading/phong.h"

#include <gtest/gtest.h>

namespace glint::phong_test {
namespace {

void expect_near(Color a, Color b, float tol = 1e-5f) {
    EXPECT_NEAR(a.r, b.r, tol);
    EXPECT_NEAR(a.g, b.g, tol);
    EXPECT_NEAR(a.b, b.b, tol);
}

Material red() {
    Material m;
    m.ka = 0.1f, m.kd = 0.7f, m.ks = 0.3f, m.shininess = 50;
    return m;
}
const Color kRed{0.9f, 0.1f, 0.1f};
const Normal3 kN{0, 1, 0};
const Vector3 kL = normalize(Vector3{1, 1, 0});

TEST(Phong, AmbientTermIsKaIaC) {
    expect_near(ambient_term(red(), kRed, Color::gray(0.1f)), {0.009f, 0.001f, 0.001f});
}

TEST(Phong, DiffuseTermIsKdCNDotL) {
    EXPECT_NEAR(diffuse_factor(kN, kL), 0.707107f, 1e-6);
    EXPECT_EQ(diffuse_factor(kN, Vector3{0, -1, 0}), 0);  // light below the surface
    // With no highlight (ks = 0): IL kd C (N.L) = 0.7 * 0.7071 * C.
    Material m = red();
    m.ks = 0;
    expect_near(light_term(m, kRed, kN, kL, {0, 1, 0}, Color::gray(1)),
                {0.445477f, 0.049497f, 0.049497f});
    // The light's intensity scales the term.
    expect_near(light_term(m, kRed, kN, kL, {0, 1, 0}, Color{2, 0, 1}), {0.890955f, 0, 0.049497f});
}

TEST(Phong, BlinnHighlightIsHDotNToTheN) {
    // V = N: H = normalize(L + V) is 22.5 degrees from N; cos(22.5)^50 = 0.019093.
    EXPECT_NEAR(specular_factor(Highlight::blinn, kN, kL, {0, 1, 0}, 50), 0.019093f, 1e-5);
    // V the mirror direction of L: H == N, the peak.
    const Vector3 mirror = normalize(Vector3{-1, 1, 0});
    EXPECT_NEAR(specular_factor(Highlight::blinn, kN, kL, mirror, 50), 1, 1e-5);
}

TEST(Phong, PhongHighlightIsRDotVToTheN) {
    // R = L mirrored about N = (-1 1 0)/sqrt2. With V = N, R.V = cos 45 and (cos 45)^50 = 2^-25.
    EXPECT_NEAR(specular_factor(Highlight::phong, kN, kL, {0, 1, 0}, 50), 2.98023e-8f, 1e-10);
    EXPECT_NEAR(specular_factor(Highlight::phong, kN, kL, normalize(Vector3{-1, 1, 0}), 50), 1,
                1e-5);
    // Shininess 1: R.V itself.
    EXPECT_NEAR(specular_factor(Highlight::phong, kN, kL, {0, 1, 0}, 1), 0.707107f, 1e-6);
}

TEST(Phong, NoHighlightWhenLightOrViewerIsBehind) {
    EXPECT_EQ(specular_factor(Highlight::blinn, kN, {0, -1, 0}, {0, 1, 0}, 10), 0);
    EXPECT_EQ(specular_factor(Highlight::phong, kN, kL, {0, -1, 0}, 10), 0);
}

TEST(Phong, HighlightIsWhiteAndAddsToDiffuse) {
    // At the mirror direction: IL (kd C (N.L) + ks) = 0.7 * 0.7071 * C + 0.3.
    const Color c = light_term(red(), kRed, kN, kL, normalize(Vector3{-1, 1, 0}), Color::gray(1));
    expect_near(c, {0.745477f, 0.349497f, 0.349497f});
}

// POV-Ray's brilliance b: kd C (N.L)^b; at N.L = cos 45, b = 2 halves the cosine's square.
TEST(Phong, BrillianceIsTheDiffuseCosinesExponent) {
    EXPECT_NEAR(diffuse_factor(kN, kL, 2), 0.5f, 1e-6);
    EXPECT_NEAR(diffuse_factor(kN, kL, 0.5f), 0.840896f, 1e-6);  // 0.7071^0.5
    EXPECT_EQ(diffuse_factor(kN, Vector3{0, -1, 0}, 2), 0);
    Material m = red();
    m.ks = 0;
    m.brilliance = 2;
    expect_near(light_term(m, kRed, kN, kL, {0, 1, 0}, Color::gray(1)), {0.315f, 0.035f, 0.035f});
}

// POV-Ray's metallic: the highlight mixed from white towards the surface colour.
TEST(Phong, MetallicTintsTheHighlight) {
    Material m = red();
    m.kd = 0;
    m.metallic = 1;
    const Vector3 mirror = normalize(Vector3{-1, 1, 0});
    expect_near(light_term(m, kRed, kN, kL, mirror, Color::gray(1)), {0.27f, 0.03f, 0.03f});
    m.metallic = 0.5f;
    expect_near(highlight_color(m, kRed), {0.95f, 0.55f, 0.55f});
}

}  // namespace
}  // namespace glint::phong_test
