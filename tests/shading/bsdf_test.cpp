// The material as a BSDF: worked values of each part, Fresnel's reflectance, reciprocity,
// samples that follow the density pdf() states (chi-square), weights that are f |cos| / pdf,
// and white furnaces: what each part reflects in all, 1 for the lossless ones and at most 1 for
// every one.
#include "glint/shading/bsdf.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "glint/sampling/random.h"
#include "glint/shading/optics.h"
#include "sampling/chi_square.h"

namespace glint {
namespace {

constexpr double kPiD = std::numbers::pi;

// wo 40 degrees from the normal +z, in the x-z plane.
const Vector3 kWo = normalize(Vector3{std::sin(0.6981317f), 0, std::cos(0.6981317f)});

BsdfInputs inputs() {
    BsdfInputs in;
    in.wo = kWo;
    in.n = in.ng = Normal3{0, 0, 1};
    return in;
}

Point2 uniform_pair(std::uint64_t i, std::uint64_t seed) {
    return {random_float(i, 0, 0, seed), random_float(i, 0, 1, seed)};
}

TEST(Bsdf, LambertIsKdColourOverPi) {
    BsdfInputs in = inputs();
    in.kd = 0.8f;
    in.color = {1, 0.5f, 0.25f};
    const Bsdf bsdf(in);
    const Color f = bsdf.eval(normalize(Vector3{0.3f, 0.2f, 0.9f}));
    EXPECT_NEAR(f.r, 0.8 / kPiD, 1e-6);
    EXPECT_NEAR(f.g, 0.4 / kPiD, 1e-6);
    EXPECT_NEAR(f.b, 0.2 / kPiD, 1e-6);
    EXPECT_EQ(bsdf.eval(Vector3{0, 0, -1}), Color{});  // below the surface: nothing
    EXPECT_NEAR(bsdf.pdf(Vector3{0, 0, 1}), 1 / kPiD, 1e-6);
}

// Veach's correction for shading normals, worked: ng = +z, ns = (0.6, 0, 0.8), wo = +z and
// wi = (0.8, 0, 0.6): |wo.ns| |wi.ng| / (|wo.ng| |wi.ns|) = 0.8 x 0.6 / (1 x 0.96) = 1/2.
TEST(Bsdf, ImportanceScattersByTheAdjointsShadingNormalCorrection) {
    BsdfInputs in = inputs();
    in.wo = {0, 0, 1};
    in.n = Normal3{0.6f, 0, 0.8f};
    in.kd = 1;
    in.reflect = 0;
    const Vector3 wi{0.8f, 0, 0.6f};
    EXPECT_NEAR(Bsdf(in).eval(wi).r, 1 / kPiD, 1e-6);
    EXPECT_NEAR(Bsdf(in, TransportMode::importance).eval(wi).r, 0.5 / kPiD, 1e-6);
    // Where the shading normal is the geometric one, importance scatters as radiance does.
    in.n = in.ng;
    EXPECT_EQ(Bsdf(in, TransportMode::importance).eval(wi), Bsdf(in).eval(wi));
}

TEST(Bsdf, TheHighlightIsLafortuneAndWillemsNormalisedPhong) {
    // ks (n+2)/(2 pi) cos^n(alpha): n = 10, alpha = 20 degrees from the mirror direction.
    BsdfInputs in = inputs();
    in.ks = 0.5f;
    in.shininess = 10;
    const Bsdf bsdf(in);
    const float mirror_angle = -0.6981317f, alpha = 0.3490659f;  // wo's mirror is at -40 deg
    const Vector3 wi{std::sin(mirror_angle + alpha), 0, std::cos(mirror_angle + alpha)};
    const double expected = 0.5 * 12 / (2 * kPiD) * std::pow(std::cos(0.3490659), 10);
    EXPECT_NEAR(bsdf.eval(wi).r, expected, 1e-5 * expected);
    // The same with wo and wi swapped: reciprocal.
    BsdfInputs swapped = in;
    swapped.wo = wi;
    EXPECT_NEAR(Bsdf(swapped).eval(kWo).r, expected, 1e-5 * expected);
}

TEST(Bsdf, FresnelReflectanceOfGlass) {
    // At normal incidence ((n1 - n2) / (n1 + n2))^2 = 0.04 for glass of 1.5 in air; at 45
    // degrees, cos_t = sqrt(1 - sin^2(45) / 2.25) = 0.88192, rs = -0.30334, rp = 0.09201:
    // F = (rs^2 + rp^2) / 2 = 0.05024. Beyond the critical angle from inside, all of it.
    EXPECT_NEAR(fresnel_dielectric(1, 1 / 1.5f), 0.04f, 1e-6f);
    EXPECT_NEAR(fresnel_dielectric(std::sqrt(0.5f), 1 / 1.5f), 0.05024f, 1e-5f);
    EXPECT_EQ(fresnel_dielectric(std::cos(0.8f), 1.5f), 1);  // 45.8 deg > asin(1/1.5) = 41.8
    EXPECT_NEAR(fresnel_dielectric(1, 1), 0, 1e-7f);
}

TEST(Bsdf, ClearGlassRefractsBySnellAndCompressesRadiance) {
    BsdfInputs in = inputs();
    in.transmit = 1;
    in.n1 = 1;
    in.n2 = 1.5f;
    const Bsdf radiance(in);
    const auto s = radiance.sample(0.5f, {0.5f, 0.5f});
    ASSERT_TRUE(s);
    EXPECT_TRUE(s->delta);
    EXPECT_TRUE(s->transmitted);
    // sin(t) = sin(40) / 1.5.
    EXPECT_NEAR(std::hypot(s->wi.x, s->wi.y), std::sin(0.6981317f) / 1.5f, 1e-6f);
    EXPECT_LT(s->wi.z, 0);
    // Radiance from inside the glass reaches the air (1 / 1.5)^2 as dense; importance does not.
    EXPECT_NEAR(s->weight.r, 1 / 2.25f, 1e-6f);
    const auto importance = Bsdf(in, TransportMode::importance).sample(0.5f, {0.5f, 0.5f});
    EXPECT_NEAR(importance->weight.r, 1, 1e-6f);
}

// Glass of 1.5 with Fresnel and a mirror coat kr 0.2, kt 0.8, wo 40 degrees from the normal:
// cos_t = sqrt(1 - sin^2(40) / 2.25) = 0.90353, rs = -0.27777, rp = 0.11962, F = 0.045734.
// The parts whole: the mirror 0.2 + 0.8 F = 0.23659 of it, the refraction 0.8 (1 - F) = 0.76341,
// compressed by 1 / 2.25 for radiance; sample() weighs the part it picks as much on average.
TEST(Bsdf, EachDeltaPartWholeWeighsWhatItScatters) {
    BsdfInputs in = inputs();
    in.reflect = 0.2f;
    in.transmit = 0.8f;
    in.n1 = 1;
    in.n2 = 1.5f;
    in.fresnel = true;
    const Bsdf bsdf(in);
    const auto mirror = bsdf.delta_part(BsdfLobe::reflect);
    const auto refracted = bsdf.delta_part(BsdfLobe::transmit);
    ASSERT_TRUE(mirror && refracted);
    EXPECT_FALSE(mirror->transmitted);
    EXPECT_TRUE(refracted->transmitted && refracted->delta && mirror->delta);
    EXPECT_EQ(mirror->pdf, 1);
    EXPECT_NEAR(mirror->weight.r, 0.23659f, 2e-5f);
    EXPECT_NEAR(refracted->weight.r, 0.76341f / 2.25f, 2e-5f);
    EXPECT_NEAR(mirror->wi.x, -kWo.x, 1e-6f);
    EXPECT_NEAR(mirror->wi.z, kWo.z, 1e-6f);
    for (const float u : {0.1f, 0.9f}) {
        const auto s = bsdf.sample(u, {0.5f, 0.5f});
        ASSERT_TRUE(s && s->delta);
        const auto& whole = s->transmitted ? refracted : mirror;
        EXPECT_NEAR(s->weight.r * s->pdf, whole->weight.r, 1e-6f);
        EXPECT_EQ(s->wi.x, whole->wi.x);
        EXPECT_EQ(s->wi.z, whole->wi.z);
    }
    // Parts that are not delta, or absent, are not given.
    EXPECT_FALSE(bsdf.delta_part(BsdfLobe::diffuse));
    in.roughness = 0.3f;
    in.transmit = 0;
    EXPECT_FALSE(Bsdf(in).delta_part(BsdfLobe::reflect));
    EXPECT_FALSE(Bsdf(in).delta_part(BsdfLobe::transmit));
}

TEST(Bsdf, TheTransmitFilterColoursWhatRefractsAndNothingElse) {
    // Clear and frosted glass with filter (1, 0.5, 0.25), index 1 on both sides: the delta
    // sample weighs the filter, the frosted lobe's f is the filter times the clear one's, and
    // the albedo's transmitted share is kt F_t.
    BsdfInputs in = inputs();
    in.transmit = 0.8f;
    in.reflect = 0.2f;
    in.transmit_filter = {1, 0.5f, 0.25f};
    const Bsdf clear(in);
    const auto s = clear.sample(0.9f, {0.5f, 0.5f});
    ASSERT_TRUE(s && s->transmitted);
    EXPECT_NEAR(s->weight.g / s->weight.r, 0.5f, 1e-6f);
    EXPECT_NEAR(s->weight.b / s->weight.r, 0.25f, 1e-6f);
    const auto mirror = clear.sample(0.1f, {0.5f, 0.5f});
    ASSERT_TRUE(mirror && !mirror->transmitted);
    EXPECT_EQ(mirror->weight.r, mirror->weight.b);
    const Color albedo = clear.albedo();
    EXPECT_NEAR(albedo.r, 1, 1e-6f);
    EXPECT_NEAR(albedo.g, 0.2f + 0.8f * 0.5f, 1e-6f);
    EXPECT_NEAR(albedo.b, 0.2f + 0.8f * 0.25f, 1e-6f);
    in.transmit_roughness = 0.3f;
    const Vector3 below = normalize(Vector3{-0.5f, 0.1f, -1});
    const Color tinted = Bsdf(in).eval(below);
    in.transmit_filter = {1, 1, 1};
    const Color white = Bsdf(in).eval(below);
    ASSERT_GT(white.r, 0);
    EXPECT_NEAR(tinted.r, white.r, 1e-6f * white.r);
    EXPECT_NEAR(tinted.g, 0.5f * white.g, 1e-6f * white.g);
    EXPECT_NEAR(tinted.b, 0.25f * white.b, 1e-6f * white.b);
}

TEST(Bsdf, TheReflectFilterColoursItsOwnReflectionNotWhatTotalReflectionMovesToIt) {
    BsdfInputs in = inputs();
    in.reflect = 0.4f;
    in.reflect_filter = {1, 0.5f, 0.25f};
    const auto s = Bsdf(in).sample(0.5f, {0.5f, 0.5f});
    ASSERT_TRUE(s && !s->transmitted && s->delta);
    EXPECT_NEAR(s->weight.g / s->weight.r, 0.5f, 1e-6f);
    EXPECT_NEAR(Bsdf(in).albedo().b, 0.4f * 0.25f, 1e-6f);
    // Inside glass of index 2, 40 degrees is past the critical angle (30): all of kt 0.4
    // reflects too, untinted: 0.4 (1, 0.5, 0.25) + 0.4.
    in.transmit = 0.4f;
    in.n1 = 2;
    in.n2 = 1;
    const Bsdf inside(in);
    EXPECT_EQ(inside.lobe_probability(BsdfLobe::transmit), 0);
    const Color albedo = inside.albedo();
    EXPECT_NEAR(albedo.r, 0.8f, 1e-6f);
    EXPECT_NEAR(albedo.g, 0.6f, 1e-6f);
    EXPECT_NEAR(albedo.b, 0.5f, 1e-6f);
}

TEST(Bsdf, FresnelSplitsTransmissionAndTotalInternalReflectionReflectsIt) {
    BsdfInputs in = inputs();
    in.transmit = 1;
    in.n1 = 1;
    in.n2 = 1.5f;
    in.fresnel = true;
    const Bsdf glass(in);
    const float f = fresnel_dielectric(std::cos(0.6981317f), 1 / 1.5f);
    EXPECT_NEAR(glass.lobe_probability(BsdfLobe::reflect), f, 1e-6f);
    EXPECT_NEAR(glass.lobe_probability(BsdfLobe::transmit), 1 - f, 1e-6f);
    // From inside the glass at 60 degrees, beyond the critical angle of asin(1 / 1.5) = 41.8.
    in.n1 = 1.5f;
    in.n2 = 1;
    in.wo = normalize(Vector3{std::sin(1.0471976f), 0, std::cos(1.0471976f)});
    const Bsdf inside(in);
    EXPECT_EQ(inside.lobe_probability(BsdfLobe::transmit), 0);
    const auto s = inside.sample(0.3f, {0.5f, 0.5f});
    ASSERT_TRUE(s);
    EXPECT_FALSE(s->transmitted);
    EXPECT_NEAR(s->weight.r, 1, 1e-6f);  // all of it reflects
}

TEST(Bsdf, PartsAddingUpToMoreThanOneAreScaledDown) {
    BsdfInputs in = inputs();
    in.kd = 0.8f;
    in.ks = 0.4f;
    in.shininess = 20;
    in.reflect = 0.4f;
    in.transmit = 0.4f;
    const Bsdf bsdf(in);
    // 2 in all: each is halved. Straight up, 40 degrees from the mirror direction.
    EXPECT_NEAR(bsdf.albedo().r, 1, 1e-6f);
    const double highlight = 0.2 * 22 / (2 * kPiD) * std::pow(std::cos(0.6981317), 20);
    EXPECT_NEAR(bsdf.eval(Vector3{0, 0, 1}).r, 0.4 / kPiD + highlight, 1e-5);
}

// ---- sampling ---------------------------------------------------------------------------------

// Four samplings tested here against their densities; together they falsely fail with
// probability 1%.
const double kSignificance = sidak_significance(0.01, 4);
constexpr std::uint64_t kSamples = 1'000'000;

// The directions sample() gives, among those it gives at all, follow pdf() normalised by its
// integral over the sphere (the rest fall through the surface the wrong way).
ChiSquareResult chi_square_of(const Bsdf& bsdf, std::uint64_t seed) {
    const ChiSquareGrid grid{-1, 1, 40, 0, 2 * kPiD, 40};
    const auto density = [&](double cos_theta, double phi) {
        const double sin_theta = std::sqrt(std::max(0.0, 1 - cos_theta * cos_theta));
        const Vector3 w{float(sin_theta * std::cos(phi)), float(sin_theta * std::sin(phi)),
                        float(cos_theta)};
        return double(bsdf.pdf(w));
    };
    std::vector<double> p = bin_probabilities_midpoint(grid, density, 24);
    double total = 0;
    for (const double x : p) total += x;
    for (double& x : p) x /= total;
    std::uint64_t i = 0;
    return chi_square_test(grid, p, kSamples, [&](std::uint64_t) {
        for (;;) {
            const std::uint64_t k = i++;
            const auto s = bsdf.sample(random_float(k, 0, 2, seed), uniform_pair(k, seed));
            if (!s) continue;
            double phi = std::atan2(double(s->wi.y), double(s->wi.x));
            if (phi < 0) phi += 2 * kPiD;
            return GridPoint{double(s->wi.z), phi};
        }
    });
}

TEST(Bsdf, DiffuseAndHighlightSamplesFollowTheirDensity) {
    BsdfInputs in = inputs();
    in.kd = 0.5f;
    in.ks = 0.4f;
    in.shininess = 20;
    const auto r = chi_square_of(Bsdf(in), 1);
    EXPECT_GT(r.p_value, kSignificance) << r.description;
}

TEST(Bsdf, GlossyReflectionSamplesFollowTheirDensity) {
    BsdfInputs in = inputs();
    in.kd = 0.2f;
    in.reflect = 0.7f;
    in.roughness = 0.3f;
    const auto r = chi_square_of(Bsdf(in), 2);
    EXPECT_GT(r.p_value, kSignificance) << r.description;
}

TEST(Bsdf, GlossyTransmissionSamplesFollowTheirDensity) {
    BsdfInputs in = inputs();
    in.kd = 0.1f;
    in.transmit = 0.8f;
    in.transmit_roughness = 0.3f;
    in.n2 = 1.5f;
    const auto r = chi_square_of(Bsdf(in), 3);
    EXPECT_GT(r.p_value, kSignificance) << r.description;
}

TEST(Bsdf, EveryPartTogetherSamplesFollowTheirDensity) {
    BsdfInputs in = inputs();
    in.kd = 0.2f;
    in.ks = 0.2f;
    in.shininess = 5;
    in.reflect = 0.2f;
    in.roughness = 0.5f;
    in.transmit = 0.2f;
    in.transmit_roughness = 0.6f;
    in.n2 = 1.3f;
    const auto r = chi_square_of(Bsdf(in), 4);
    EXPECT_GT(r.p_value, kSignificance) << r.description;
}

TEST(Bsdf, ASamplesWeightIsFTimesCosineOverPdf) {
    BsdfInputs in = inputs();
    in.kd = 0.3f;
    in.ks = 0.3f;
    in.shininess = 8;
    in.reflect = 0.2f;
    in.roughness = 0.4f;
    const Bsdf bsdf(in);
    for (std::uint64_t i = 0; i < 1000; ++i) {
        const auto s = bsdf.sample(random_float(i, 0, 2, 9), uniform_pair(i, 9));
        if (!s) continue;
        EXPECT_FALSE(s->delta);
        const Color expected = bsdf.eval(s->wi) * (std::abs(s->wi.z) / bsdf.pdf(s->wi));
        EXPECT_NEAR(s->weight.r, expected.r, 1e-5f * expected.r);
        EXPECT_EQ(s->pdf, bsdf.pdf(s->wi));
    }
}

// ---- white furnace ----------------------------------------------------------------------------

// What the BSDF scatters in all, light arriving along wo: the mean of the samples' weights.
double scattered(const BsdfInputs& in, TransportMode mode = TransportMode::radiance) {
    const Bsdf bsdf(in, mode);
    constexpr int n = 200000;
    double sum = 0;
    for (int i = 0; i < n; ++i) {
        const auto s =
            bsdf.sample(random_float(std::uint64_t(i), 0, 2, 5), uniform_pair(std::uint64_t(i), 5));
        if (s) sum += (s->weight.r + s->weight.g + s->weight.b) / 3;
    }
    return sum / n;
}

TEST(Bsdf, LosslessPartsScatterEverythingAndNoneMoreThanAll) {
    BsdfInputs lambert = inputs(), mirror = inputs(), glass = inputs(), frosted = inputs();
    lambert.kd = 1;
    mirror.reflect = 1;
    glass.transmit = 1;
    glass.fresnel = true;
    frosted.transmit = 1;
    frosted.transmit_roughness = 0.2f;
    EXPECT_NEAR(scattered(lambert), 1, 0.005);
    EXPECT_NEAR(scattered(mirror), 1, 1e-6);
    EXPECT_NEAR(scattered(glass), 1, 0.005);  // index 1: Fresnel reflects nothing
    EXPECT_NEAR(scattered(glass, TransportMode::importance), 1, 0.005);
    // A narrow frosted lobe through the surface: everything but what tips back through it.
    EXPECT_NEAR(scattered(frosted), 1, 0.01);
    // Glass of 1.5 with Fresnel: what reflects and what refracts add up to 1 for importance
    // (radiance is compressed as it enters the denser medium).
    glass.n2 = 1.5f;
    EXPECT_NEAR(scattered(glass, TransportMode::importance), 1, 1e-6);
    // Normalised Phong keeps within ks; so does every mixture.
    for (const float shininess : {0.0f, 1.0f, 10.0f, 100.0f}) {
        BsdfInputs phong = inputs();
        phong.ks = 1;
        phong.shininess = shininess;
        EXPECT_LE(scattered(phong), 1.005) << shininess;
    }
    BsdfInputs all = inputs();
    all.kd = all.ks = all.reflect = all.transmit = 0.5f;
    all.roughness = 0.3f;
    EXPECT_LE(scattered(all, TransportMode::importance), 1.005);
}

}  // namespace
}  // namespace glint
