// The Standard Procedural Databases rendered as the SPD prescribes (512x512, depth 5, no adaptive
// cut-off): ray counts within 10% of the SPD's published statistics, and images that agree in
// view and geometry with POV-Ray's renders of the same databases. The databases are third-party
// data outside the repository (../shared/data/spd); without them the tests are skipped.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "glint/image/image_io.h"
#include "glint/image/srgb.h"
#include "glint/render/render.h"
#include "glint/scene/nff/nff_to_scene.h"

namespace glint {
namespace {

namespace fs = std::filesystem;

const fs::path kSpd = fs::path(GLINT_SOURCE_DIR) / "../shared/data/spd";

struct Published {
    const char* file;
    std::uint64_t eye_hits, reflected, refracted, shadow;
};

// From the SPD's README (513 x 513 corner rays; teapot at its 1987 size factor 12).
const Published kPublished[] = {
    {"balls.nff", 263169, 175095, 0, 954368},
    {"gears.nff", 245086, 304643, 207564, 2246955},
    {"mount.nff", 173125, 354769, 354769, 412922},
    {"rings.nff", 263169, 315236, 0, 1085002},
    {"teapot-s12.nff.gz", 161120, 225248, 0, 407656},
    {"tetra.nff", 49788, 0, 0, 46112},
    {"tree.nff", 169836, 0, 0, 1097419},
};

void expect_within_ten_percent(std::uint64_t ours, std::uint64_t published, const char* what) {
    if (published == 0) {
        EXPECT_EQ(ours, 0u) << what;
        return;
    }
    const double ratio = double(ours) / double(published);
    EXPECT_NEAR(ratio, 1, 0.10) << what << ": " << ours << " against " << published;
}

class SpdStatistics : public ::testing::TestWithParam<Published> {};

TEST_P(SpdStatistics, RayCountsAreWithinTenPercentOfThePublishedOnes) {
    const Published& p = GetParam();
    if (!fs::exists(kSpd / p.file)) GTEST_SKIP() << kSpd / p.file << " is not here";
    const RenderResult r = render(World(load_nff_scene(kSpd / p.file)), {});
    ASSERT_EQ(r.image.width, 512);
    expect_within_ten_percent(r.rays.primary_hits, p.eye_hits, "eye rays that hit");
    expect_within_ten_percent(r.rays[RayKind::reflected], p.reflected, "reflection rays");
    expect_within_ten_percent(r.rays[RayKind::refracted], p.refracted, "refraction rays");
    expect_within_ten_percent(r.rays[RayKind::shadow], p.shadow, "shadow rays");
}

INSTANTIATE_TEST_SUITE_P(Databases, SpdStatistics, ::testing::ValuesIn(kPublished),
                         [](const ::testing::TestParamInfo<Published>& param) {
                             std::string name = param.param.file;
                             return name.substr(0, name.find_first_of(".-"));
                         });

// POV-Ray's reference pixels are round(255 x linear value) in files tagged sRGB: read_image
// decodes them as sRGB, so encoding again recovers the linear values.
float pov_linear(float decoded) { return linear_to_srgb(decoded); }

float luminance(Color c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

bool is_background(Color c, Color background, float tolerance) {
    return std::abs(c.r - background.r) <= tolerance && std::abs(c.g - background.g) <= tolerance &&
           std::abs(c.b - background.b) <= tolerance;
}

class SpdImages : public ::testing::TestWithParam<const char*> {};

// View and geometry, not brightness (NFF lacks POV-Ray's ambient and highlight strengths):
// where each renderer sees the background, and how brightness varies across the image.
TEST_P(SpdImages, AgreeWithPovRayInViewAndGeometry) {
    const std::string name = GetParam();
    const fs::path reference = kSpd / "povray-reference" / (name + "_noaa.png");
    if (!fs::exists(reference)) GTEST_SKIP() << reference << " is not here";
    const Scene scene = load_nff_scene(kSpd / (name + ".nff"));
    const Image ours = render(World(scene), {}).image;
    const Image pov = read_image(reference);
    ASSERT_EQ(ours.width, pov.width);
    ASSERT_EQ(ours.height, pov.height);

    // Background masks agree on nearly every pixel (silhouettes may differ by a pixel), and
    // where both see an object, brightness varies alike: the same faces lit, the same shadows.
    const Color bg = scene.settings.background;
    int agree = 0;
    double n = 0, sa = 0, sb = 0, sab = 0, saa = 0, sbb = 0;
    for (int y = 0; y < ours.height; ++y)
        for (int x = 0; x < ours.width; ++x) {
            const Color o = ours.at(x, y);
            const Color p = pov.at(x, y);
            const Color pl{pov_linear(p.r), pov_linear(p.g), pov_linear(p.b)};
            const bool ours_background = is_background(o, bg, 1e-4f);
            const bool pov_background = is_background(pl, bg, 1.5f / 255);
            agree += ours_background == pov_background;
            if (ours_background || pov_background) continue;
            const double a = std::min(luminance(o), 1.0f), b = luminance(pl);
            n += 1, sa += a, sb += b, sab += a * b, saa += a * a, sbb += b * b;
        }
    const double agreement = double(agree) / (ours.width * ours.height);
    EXPECT_GT(agreement, 0.98) << name;
    const double correlation =
        (sab - sa * sb / n) / std::sqrt((saa - sa * sa / n) * (sbb - sb * sb / n));
    EXPECT_GT(correlation, 0.7) << name;  // shading conventions differ; geometry does not
    std::printf("%s: background agreement %.4f, brightness correlation on objects %.4f\n",
                name.c_str(), agreement, correlation);
}

INSTANTIATE_TEST_SUITE_P(Databases, SpdImages, ::testing::Values("balls", "teapot", "tetra"));

}  // namespace
}  // namespace glint
