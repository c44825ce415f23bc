#include "glint/shading/spectrum.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "glint/sampling/random.h"

namespace glint::spectrum_test {

void expect_near(Color a, Color b, float tol) {
    EXPECT_NEAR(a.r, b.r, tol);
    EXPECT_NEAR(a.g, b.g, tol);
    EXPECT_NEAR(a.b, b.b, tol);
}

TEST(Spectrum, D65WhiteIsSrgbWhite) {
    expect_near(xyz_to_linear_srgb({0.95047f, 1, 1.08883f}), {1, 1, 1}, 1e-3f);
}

TEST(Spectrum, SrgbPrimariesComeBackFromTheirXyz) {
    // The red primary of sRGB (x, y) = (0.64, 0.33) with its luminance Y = 0.2126.
    const float y = 0.2126f;
    const Xyz red{0.64f / 0.33f * y, y, (1 - 0.64f - 0.33f) / 0.33f * y};
    expect_near(xyz_to_linear_srgb(red), {1, 0, 0}, 2e-3f);
}

TEST(Spectrum, WeightIntegratesToWhite) {
    // The weight is piecewise linear with knots every 5 nm, so the trapezoid rule on a 0.1 nm
    // grid is its exact integral: an equal-energy spectrum gives (1, 1, 1).
    double r = 0, g = 0, b = 0;
    const double h = 0.1;
    const int steps = 4700;
    for (int i = 0; i <= steps; ++i) {
        const double w = (i == 0 || i == steps) ? h / 2 : h;
        const Color c = wavelength_to_rgb_weight(float(360 + i * h));
        r += w * c.r;
        g += w * c.g;
        b += w * c.b;
    }
    EXPECT_NEAR(r, 1, 1e-4);
    EXPECT_NEAR(g, 1, 1e-4);
    EXPECT_NEAR(b, 1, 1e-4);
}

TEST(Spectrum, WeightOverPdfLeavesAColourUnchangedOnAverage) {
    // Uniform wavelengths over [360, 830] nm: pdf 1 / 470 per nm.
    const Color color{0.2f, 0.5f, 0.8f};
    const float pdf = 1 / (kMaxWavelength - kMinWavelength);
    const int n = 400000;
    double r = 0, g = 0, b = 0;
    for (int i = 0; i < n; ++i) {
        const float lambda = kMinWavelength + random_float(0, i, 0, 7) * 470;
        const Color c = color * wavelength_to_rgb_weight(lambda) / pdf;
        r += c.r;
        g += c.g;
        b += c.b;
    }
    // A sample's standard deviation is below 3 times the mean (2.9 for red): with 400000
    // samples the standard error is under 0.5%, and 2% is over 4 of them.
    EXPECT_NEAR(r / n, 0.2, 0.02 * 0.2);
    EXPECT_NEAR(g / n, 0.5, 0.02 * 0.5);
    EXPECT_NEAR(b / n, 0.8, 0.02 * 0.8);
}

TEST(Spectrum, WavelengthsGiveTheRainbowsColours) {
    const Color blue = wavelength_to_rgb_weight(450);
    EXPECT_GT(blue.b, blue.r);
    EXPECT_GT(blue.b, blue.g);
    const Color green = wavelength_to_rgb_weight(530);
    EXPECT_GT(green.g, green.r);
    EXPECT_GT(green.g, green.b);
    const Color red = wavelength_to_rgb_weight(630);
    EXPECT_GT(red.r, red.g);
    EXPECT_GT(red.r, red.b);
    // Hand computed from the table, the matrix and the channel integrals (128.75, 101.34, 97.14
    // for the unscaled sRGB of an equal-energy spectrum): 630 nm gives red 0.0130 per nm.
    EXPECT_NEAR(red.r, 0.013005f, 2e-5f);
}

TEST(Spectrum, SpectralColoursOutsideTheGamutHaveNegativeChannels) {
    // 500 nm (cyan) is outside the sRGB triangle: its red is negative.
    EXPECT_LT(wavelength_to_rgb_weight(500).r, 0);
    expect_near(wavelength_to_rgb_weight(300), {0, 0, 0}, 0);
    expect_near(wavelength_to_rgb_weight(900), {0, 0, 0}, 0);
}

Dispersion bk7() {
    // Schott N-BK7 from its data sheet.
    return {DispersionModel::sellmeier,
            {1.03961212f, 0.231792344f, 1.01046945f, 0.00600069867f, 0.0200179144f, 103.560653f}};
}

TEST(Dispersion, SellmeierGivesBk7sCatalogueIndices) {
    const Dispersion d = bk7();
    const float n_d = refractive_index(d, 1.5f, kReferenceWavelength);
    const float n_f = refractive_index(d, 1.5f, 486.13f);
    const float n_c = refractive_index(d, 1.5f, 656.27f);
    EXPECT_NEAR(n_d, 1.5168f, 1e-4f);
    EXPECT_NEAR(n_f, 1.5224f, 1e-4f);
    EXPECT_NEAR(n_c, 1.5143f, 1e-4f);
    EXPECT_NEAR((n_d - 1) / (n_f - n_c), 64.17f, 0.1f);
    EXPECT_EQ(describe_problem(d, 1.5f), "");
}

TEST(Dispersion, CauchyWorkedExample) {
    // n = A + B / lambda^2: 1.5046 + 0.00420 / 0.5^2 = 1.5214 at 500 nm.
    const Dispersion d{DispersionModel::cauchy, {1.5046f, 0.00420f}};
    EXPECT_NEAR(refractive_index(d, 1, 500), 1.5214f, 1e-5f);
    // Blue bends more than red.
    EXPECT_GT(refractive_index(d, 1, 450), refractive_index(d, 1, 650));
}

TEST(Dispersion, CauchyFromAbbeReproducesNdAndV) {
    const Dispersion d = cauchy_from_abbe(1.5168f, 64.17f);
    // By hand: B = 0.5168 / 64.17 / (1 / 0.48613^2 - 1 / 0.65627^2) = 0.0042173 um^2,
    // A = 1.5168 - B / 0.58756^2 = 1.504584.
    EXPECT_EQ(d.model, DispersionModel::cauchy);
    EXPECT_NEAR(d.c[0], 1.504584f, 2e-6f);
    EXPECT_NEAR(d.c[1], 0.0042173f, 2e-7f);
    const float n_d = refractive_index(d, 1, kReferenceWavelength);
    const float n_f = refractive_index(d, 1, 486.13f);
    const float n_c = refractive_index(d, 1, 656.27f);
    EXPECT_NEAR(n_d, 1.5168f, 1e-6f);
    EXPECT_NEAR((n_d - 1) / (n_f - n_c), 64.17f, 0.02f);
}

TEST(Dispersion, NoneReturnsTheIorWhateverTheWavelength) {
    const Dispersion d;
    EXPECT_EQ(refractive_index(d, 1.33f, 400), 1.33f);
    EXPECT_EQ(refractive_index(d, 1.33f, 700), 1.33f);
    EXPECT_EQ(describe_problem(d, 1.33f), "");
    EXPECT_EQ(describe_problem(d, 0), "index of refraction must be finite and > 0, got 0");
    EXPECT_NE(describe_problem(d, NAN), "");
}

TEST(Dispersion, SellmeierPoleInsideTheRangeIsAProblem) {
    // C1 = 0.17 um^2 puts the pole at sqrt(0.17) um = 412 nm.
    Dispersion d = bk7();
    d.c[3] = 0.17f;
    EXPECT_EQ(describe_problem(d, 1.5f),
              "sellmeier coefficient C1 = 0.17 um^2 puts a pole at 412 nm, inside 360-830 nm");
}

TEST(Dispersion, SellmeierWithoutARealIndexIsAProblem) {
    // n^2 = 1 - 2 lambda^2 / (lambda^2 - 0.01): below zero from 360 nm on (pole at 100 nm).
    const Dispersion d{DispersionModel::sellmeier, {-2, 0, 0, 0.01f, 0, 0}};
    EXPECT_EQ(describe_problem(d, 1.5f),
              "sellmeier coefficients give no real index of refraction at 360 nm");
}

TEST(Dispersion, CauchyIndexBelowZeroIsAProblemBelowOneIsNot) {
    // n = -0.5 + 0.2 / lambda^2: 1.04 at 360 nm, zero at sqrt(0.4) um = 632.5 nm, and
    // -0.5 + 0.2 / 0.633^2 = -0.00085977 at 633 nm, the first whole nanometre below zero.
    const Dispersion negative{DispersionModel::cauchy, {-0.5f, 0.2f}};
    const std::string problem = describe_problem(negative, 1);
    EXPECT_EQ(problem.rfind("cauchy coefficients give an index of refraction of -0.00085", 0), 0u)
        << problem;
    EXPECT_NE(problem.find(" at 633 nm; it must be finite and > 0"), std::string::npos) << problem;
    // An index between 0 and 1 exists (metals, X-rays): allowed.
    const Dispersion below_one{DispersionModel::cauchy, {0.5f, 0.01f}};
    EXPECT_EQ(describe_problem(below_one, 1), "");
    const Dispersion not_finite{DispersionModel::cauchy, {NAN, 0.01f}};
    EXPECT_EQ(describe_problem(not_finite, 1), "cauchy coefficients must be finite, got nan");
}

}  // namespace glint::spectrum_test
