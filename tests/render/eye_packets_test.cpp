// Eye rays traced in packets of neighbouring pixels (render.cpp) give the image of eye rays traced
// one by one, bit for bit, and the same ray counts: over the feature scenes of the integrators
// that take packets, with tiles and images whose sides are not multiples of the 4 x 2 blocks,
// filters that reach across pixels, and lenses, shutters, pencils and dispersion.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "common/under_sanitizer.h"
#include "glint/render/render.h"
#include "glint/render/world.h"
#include "glint/scene/load_scene.h"

namespace glint::eye_packets_test {

struct Case {
    const char* scene;
    IntegratorKind integrator;
};

constexpr Case kCases[] = {
    {"jacks.nff", IntegratorKind::whitted},               // NFF: polygons, cylinders, a plane
    {"meshes.yaml", IntegratorKind::whitted},             // meshes traced whole and placed
    {"refraction.yaml", IntegratorKind::whitted},         // the ray tree below the eye ray
    {"texture-filtering.yaml", IntegratorKind::whitted},  // eye rays carry their pencils
    {"csg.yaml", IntegratorKind::distributed},
    {"depth-of-field.yaml", IntegratorKind::distributed},  // a lens: rays from many points
    {"motion-blur.yaml", IntegratorKind::distributed},     // rays at many times
    {"dispersion.yaml", IntegratorKind::distributed},
    {"soft-shadows.yaml", IntegratorKind::distributed},
    {"media.yaml", IntegratorKind::distributed},
    {"cornell-box.yaml", IntegratorKind::path},
    {"sky.yaml", IntegratorKind::path},
};

TEST(EyePackets, TheImageIsTheSameBitForBitAsWithRaysOneByOne) {
    for (const Case& c : kCases) {
        Scene scene =
            load_scene(std::filesystem::path(GLINT_SOURCE_DIR) / "scenes/features" / c.scene);
        scene.settings.integrator = c.integrator;
        scene.settings.width = 37;
        scene.settings.height = 23;
        scene.settings.adaptive.reset();
        scene.settings.samples_per_pixel = testing::kUnderSanitizer ? 2 : 3;
        const World world(std::move(scene));
        RenderOptions alone;
        alone.eye_packets = false;
        alone.tile_size = 7;
        const RenderResult expected = render(world, alone);
        ASSERT_TRUE(expected.complete) << c.scene;
        for (const int tile_size : {7, 16}) {
            RenderOptions packets = alone;
            packets.eye_packets = true;
            packets.tile_size = tile_size;
            const RenderResult got = render(world, packets);
            // operator== on floats, not a tolerance.
            EXPECT_TRUE(got.image.pixels == expected.image.pixels)
                << c.scene << ", tiles of " << tile_size;
            EXPECT_EQ(got.rays, expected.rays) << c.scene << ", tiles of " << tile_size;
            EXPECT_EQ(got.bad_samples.count, expected.bad_samples.count) << c.scene;
        }
    }
}

TEST(EyePackets, FiltersThatReachAcrossPixelsSumTheSame) {
    Scene scene = load_scene(std::filesystem::path(GLINT_SOURCE_DIR) / "scenes/features/jacks.nff");
    scene.settings.width = 30;
    scene.settings.height = 21;
    scene.settings.samples_per_pixel = 4;
    scene.settings.sampler = SamplerKind::jittered;
    for (const FilterSpec filter :
         {FilterSpec{FilterKind::gaussian, 1.5f}, FilterSpec{FilterKind::box, 0.5f}}) {
        scene.settings.filter = filter;
        const World world(scene);
        RenderOptions alone;
        alone.eye_packets = false;
        alone.seed = 3;
        RenderOptions packets = alone;
        packets.eye_packets = true;
        EXPECT_TRUE(render(world, packets).image.pixels == render(world, alone).image.pixels)
            << filter_names()[std::size_t(filter.kind)];
    }
}

}  // namespace glint::eye_packets_test
