// Statistical image tests for the stochastic integrators: a scene rendered with few samples per
// pixel must agree with a high-sample reference within the noise it has, not byte for byte.
// Four renders with different seeds measure each pixel's variance (their sample variance); over
// 8 x 8 blocks, the mean of the renders must lie within 5 standard errors of the reference's
// (plus 0.002 for rounding that differs across compilers). Two renders were too few: where a
// block's noise is a few pixels that either see a sliver of a light or not, two renders that
// happen to agree there measure almost no noise. Each render takes 64 samples a pixel: with 16,
// a far lamp's out-of-focus hexagon, which a sample sees through 1/64 of the lens, was seen by
// no sample of a block in all four renders for one seed set in four, and a block's noise that
// no render shows cannot be measured. A box filter of one pixel keeps pixels independent, so
// that a block's variance is the sum of its pixels'.
// GLINT_UPDATE_GOLDEN=1 rewrites the references (tests/golden/statistical/*.exr) with
// kReferenceSamples a pixel; look at every one before committing it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "common/under_sanitizer.h"
#include "glint/image/image_io.h"
#include "glint/math/constants.h"
#include "glint/render/render.h"
#include "glint/scene/load_scene.h"

namespace glint {
namespace {

namespace fs = std::filesystem;

constexpr int kWidth = 96, kHeight = 64, kBlock = 8;
constexpr int kSamples = 64, kReferenceSamples = 1024;
constexpr double kMaxStandardErrors = 5, kAllowance = 0.002;

Image render_scene(Scene scene, int samples, std::uint64_t seed) {
    scene.settings.width = kWidth;
    scene.settings.height = kHeight;
    scene.settings.samples_per_pixel = samples;
    scene.settings.filter = FilterSpec{FilterKind::box, 0.5f};
    RenderOptions options;
    options.seed = seed;
    const RenderResult result = render(World(std::move(scene)), options);
    EXPECT_EQ(result.bad_samples.count, 0u);
    return result.image;
}

constexpr int kRenders = 4;

// kRenders renders of seeds 1, 2, ...
std::vector<Image> renders_of(const Scene& scene, int samples) {
    std::vector<Image> renders;
    for (int seed = 1; seed <= kRenders; ++seed)
        renders.push_back(render_scene(scene, samples, std::uint64_t(seed)));
    return renders;
}

float channel(const Color& c, int i) { return i == 0 ? c.r : i == 1 ? c.g : c.b; }

// Over 8 x 8 blocks, the mean of the renders (of different seeds) must lie within 5 standard
// errors of the reference's, each pixel's variance the renders' sample variance, the reference's
// own noise its share of the samples, plus 0.002 and `relative` of the reference. The worst
// block's distance as a fraction of its bound.
// Blocks for which `skip(bx, by)` holds are left out.
template <class Skip = bool (*)(int, int)>
double expect_agreement(
    const std::string& name, const Image& reference, const std::vector<Image>& renders,
    double reference_share, double relative = 0, Skip skip = [](int, int) { return false; }) {
    int failures = 0;
    double worst = 0;
    const double k = double(renders.size());
    for (int by = 0; by < kHeight; by += kBlock)
        for (int bx = 0; bx < kWidth; bx += kBlock)
            for (int i = 0; i < 3; ++i) {
                if (skip(bx, by)) continue;
                double mean = 0, expected = 0, variance = 0;
                for (int y = by; y < by + kBlock; ++y)
                    for (int x = bx; x < bx + kBlock; ++x) {
                        double sum = 0, squares = 0;
                        for (const Image& r : renders) {
                            const double v = channel(r.at(x, y), i);
                            sum += v;
                            squares += v * v;
                        }
                        mean += sum / k;
                        expected += channel(reference.at(x, y), i);
                        variance +=
                            std::max(0.0, (squares - sum * sum / k) / (k - 1));  // one render's
                    }
                const double n = kBlock * kBlock;
                mean /= n;
                expected /= n;
                const double error = std::sqrt(variance / (n * n) * (1 / k + reference_share));
                const double off = std::abs(mean - expected);
                const double bound = kMaxStandardErrors * error + kAllowance + relative * expected;
                worst = std::max(worst, off / bound);
                if (off > bound && ++failures <= 5) {
                    ADD_FAILURE() << name << ": block at (" << bx << ", " << by << ") channel " << i
                                  << ": mean " << mean << ", reference " << expected
                                  << ", standard error " << error;
                }
            }
    EXPECT_EQ(failures, 0) << name;
    return worst;
}

class StatisticalImage : public ::testing::TestWithParam<std::string> {};

TEST_P(StatisticalImage, AgreesWithTheHighSampleReferenceWithinItsNoise) {
    const std::string name = GetParam();
    const fs::path source = GLINT_SOURCE_DIR;
    const fs::path reference_file =
        source / "tests/golden/statistical" / (fs::path(name).stem().string() + ".exr");
    const Scene scene = load_scene(source / "scenes" / name);
    if (std::getenv("GLINT_UPDATE_GOLDEN")) {
        fs::create_directories(reference_file.parent_path());
        write_image(reference_file, render_scene(scene, kReferenceSamples, 0));
        GTEST_SKIP() << "wrote " << reference_file;
    }
    const Image reference = read_image(reference_file);
    const std::vector<Image> renders = renders_of(scene, kSamples);
    ASSERT_EQ(reference.width, kWidth);
    ASSERT_EQ(reference.height, kHeight);

    // The reference's own noise is that of kReferenceSamples samples against a render's kSamples.
    const double worst =
        expect_agreement(name, reference, renders, double(kSamples) / kReferenceSamples);
    RecordProperty("worst_fraction_of_bound", std::to_string(worst));
}

// The light and photon integrators converge to the path tracer's image: the Cornell box of both
// against the path tracer's reference, as above. The photons' noise is shared by the pixels of a
// pass, and each pass's image is blurred by its radius: they may be off by a further 4%.
TEST(StatisticalImage, TheLightAndPhotonIntegratorsConvergeToThePathTracersCornellBox) {
    const fs::path source = GLINT_SOURCE_DIR;
    const Image reference = read_image(source / "tests/golden/statistical/cornell-box.exr");
    Scene scene = load_scene(source / "scenes/features/cornell-box.yaml");
    scene.settings.integrator = IntegratorKind::light;
    const int light_samples = testing::kUnderSanitizer ? 16 : 64;
    expect_agreement("light", reference, renders_of(scene, light_samples),
                     double(light_samples) / kReferenceSamples);
    scene.settings.integrator = IntegratorKind::photon;
    scene.settings.photons.per_pass = testing::kUnderSanitizer ? 10000 : 40000;
    const int photon_samples = testing::kUnderSanitizer ? 4 : 16;
    expect_agreement("photon", reference, renders_of(scene, photon_samples),
                     double(photon_samples) / kReferenceSamples, 0.04);
}

// The caustics scene, whose caustics the path tracer finds only by chance: its reference is the
// path tracer's with many more samples, and the photon and light integrators, which find them
// from the light, must agree with it. The light tracer cannot see what lies behind glass or in a
// mirror (no particle can be joined to the eye through them): the blocks that show any glass,
// mirror or metal are left out of its comparison.
TEST(StatisticalImage, ThePhotonAndLightIntegratorsAgreeWithThePathTracerOnCaustics) {
    constexpr int kCausticsReferenceSamples = 16384;
    const fs::path source = GLINT_SOURCE_DIR;
    const fs::path reference_file = source / "tests/golden/statistical/caustics.exr";
    Scene scene = load_scene(source / "scenes/features/caustics.yaml");
    scene.settings.integrator = IntegratorKind::path;
    if (std::getenv("GLINT_UPDATE_GOLDEN")) {
        write_image(reference_file, render_scene(scene, kCausticsReferenceSamples, 0));
        GTEST_SKIP() << "wrote " << reference_file;
    }
    const Image reference = read_image(reference_file);

    scene.settings.integrator = IntegratorKind::photon;
    scene.settings.photons.per_pass = testing::kUnderSanitizer ? 50000 : 100000;
    const int photon_samples = testing::kUnderSanitizer ? 4 : 16;
    RecordProperty(
        "photon_worst_fraction_of_bound",
        std::to_string(expect_agreement("photon", reference, renders_of(scene, photon_samples),
                                        double(photon_samples) / kCausticsReferenceSamples, 0.04)));

    // The blocks where an eye ray through some pixel's centre first meets a delta surface.
    scene.settings.width = kWidth;
    scene.settings.height = kHeight;
    const World world(scene);
    std::vector<bool> specular(std::size_t(kWidth / kBlock) * (kHeight / kBlock));
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const Ray ray = world.camera().generate_ray({float(x) + 0.5f, float(y) + 0.5f});
            const auto hit = world.intersect(ray, {0, kInfinity}, kVisibleToCameraRays);
            if (!hit) continue;
            const Material& m = world.material_of(hit->primitive);
            if (m.reflect > 0 || m.transmit > 0)
                specular[std::size_t(y / kBlock) * (kWidth / kBlock) + std::size_t(x / kBlock)] =
                    true;
        }
    scene.settings.integrator = IntegratorKind::light;
    const int light_samples = testing::kUnderSanitizer ? 16 : 64;
    RecordProperty("light_worst_fraction_of_bound",
                   std::to_string(expect_agreement(
                       "light", reference, renders_of(scene, light_samples),
                       double(light_samples) / kCausticsReferenceSamples, 0, [&](int bx, int by) {
                           return bool(specular[std::size_t(by / kBlock) * (kWidth / kBlock) +
                                                std::size_t(bx / kBlock)]);
                       })));
}

INSTANTIATE_TEST_SUITE_P(Scenes, StatisticalImage,
                         ::testing::Values("features/soft-shadows.yaml", "features/glossy.yaml",
                                           "features/translucency.yaml",
                                           "features/depth-of-field.yaml",
                                           "features/motion-blur.yaml", "features/dispersion.yaml",
                                           "distributed-showcase.yaml",
                                           "features/cornell-box.yaml"),
                         [](const ::testing::TestParamInfo<std::string>& param) {
                             std::string id = fs::path(param.param).stem().string();
                             for (char& c : id)
                                 if (c == '-') c = '_';
                             return id;
                         });

}  // namespace
}  // namespace glint
