// The render's memory estimate: its counts and sizes worked out by hand, sizes as users write
// them, and the estimate against what a built structure and film take.
#include "glint/render/memory_estimate.h"

#include <gtest/gtest.h>

#include "glint/geometry/triangle_mesh.h"
#include "glint/render/render_state.h"
#include "glint/render/world.h"

namespace glint {
namespace {

Scene spheres_and_a_mesh(int spheres, int triangles) {
    Scene scene;
    scene.settings.width = 400;
    scene.settings.height = 300;
    scene.materials.push_back({});
    for (int i = 0; i < spheres; ++i) scene.objects.push_back({Sphere{{float(i), 0, 0}, 0.4f}});
    MeshData arrays;
    for (int i = 0; i < triangles; ++i) {
        const auto first = std::uint32_t(arrays.positions.size());
        arrays.positions.push_back({float(i), 0, 0});
        arrays.positions.push_back({float(i) + 1, 0, 0});
        arrays.positions.push_back({float(i), 1, 0});
        arrays.triangles.push_back({first, first + 1, first + 2});
    }
    scene.objects.push_back({TriangleMesh{build_mesh(std::move(arrays)).mesh}});
    return scene;
}

TEST(MemoryEstimate, CountsEveryTriangleAndEveryPixel) {
    Scene scene = spheres_and_a_mesh(10, 1000);
    const std::uint64_t pixels = 400 * 300, buffers = 4 << 20;
    const MemoryEstimate box = estimate_render_memory(scene, AccelKind::bvh);
    EXPECT_EQ(box.references, 1010u);
    // The one-pixel box: its float sums (16 bytes) and samples taken (4), the image (12) and
    // the 8-bit copy (4).
    EXPECT_EQ(box.film, pixels * (16 + 4 + 12 + 4) + buffers);
    EXPECT_EQ(estimate_render_memory(scene, AccelKind::bvh, {.samples_image = true}).film,
              pixels * (16 + 4 + 12 + 4 + 24) + buffers);
    // A resume file read: its bytes and the state unpacked, each at most the state's 20.
    EXPECT_EQ(estimate_render_memory(scene, AccelKind::bvh, {.resuming = true}).film,
              pixels * (16 + 4 + 12 + 4 + 2 * 20) + buffers);

    scene.settings.filter = FilterSpec{FilterKind::gaussian, 1.5f, 0.5f};
    // Fixed-point sums: four 128-bit integers a pixel.
    EXPECT_EQ(estimate_render_memory(scene, AccelKind::bvh).film,
              pixels * (64 + 4 + 12 + 4) + buffers);
    // Adaptive sampling keeps each pixel's error: a count, a mean and a sum of squares; its
    // samples count for their own pixels alone, in float sums.
    scene.settings.adaptive = AdaptiveSampling{0.01f, 16};
    EXPECT_EQ(estimate_render_memory(scene, AccelKind::bvh).film,
              pixels * (16 + 4 + 24 + 12 + 4) + buffers);
    EXPECT_EQ(box.total(), box.acceleration + box.film);
}

TEST(MemoryEstimate, IsNoLessThanWhatTheFilmAndStateTake) {
    Scene scene = spheres_and_a_mesh(1, 1);
    scene.settings.adaptive = AdaptiveSampling{0.01f, 16};
    for (const FilterSpec filter :
         {FilterSpec{FilterKind::box, 0.5f}, FilterSpec{FilterKind::gaussian, 1.5f, 0.5f}}) {
        scene.settings.filter = filter;
        const RenderState state(scene.settings, 32, 16);
        const std::uint64_t held = state.film.sums().size() * sizeof(PixelSum) +
                                   state.film.box_sums().size() * sizeof(BoxSum) +
                                   state.samples.size() * sizeof(std::uint32_t) +
                                   state.errors.size() * sizeof(PixelError) +
                                   state.film.resolve().pixels.size() * sizeof(Color);
        // Without the files' buffers, which would hide a pixel's bytes left out.
        EXPECT_GE(estimate_render_memory(scene, AccelKind::list).film - (4 << 20), held);
    }
}

TEST(MemoryEstimate, IsNoLessThanWhatTheBuiltStructureTakes) {
    for (const AccelKind accel :
         {AccelKind::list, AccelKind::bvh, AccelKind::grid, AccelKind::kdtree}) {
        Scene scene = spheres_and_a_mesh(2000, 20000);
        const MemoryEstimate estimate = estimate_render_memory(scene, accel);
        const World world(std::move(scene), accel);
        const std::size_t built = make_aggregate(accel, world.primitives())->memory_bytes();
        EXPECT_GE(estimate.acceleration, built) << accel_name(accel);
        // And not wildly more (the kd-tree's allowance is for its worst scenes).
        EXPECT_LE(estimate.acceleration, 16 * built + (1 << 20)) << accel_name(accel);
    }
}

TEST(MemoryEstimate, SizesAsUsersWriteThem) {
    EXPECT_EQ(parse_bytes("512"), 512u);
    EXPECT_EQ(parse_bytes("512B"), 512u);
    EXPECT_EQ(parse_bytes("4K"), 4096u);
    EXPECT_EQ(parse_bytes("4k"), 4096u);
    EXPECT_EQ(parse_bytes("64M"), 64u << 20);
    EXPECT_EQ(parse_bytes("64MiB"), 64u << 20);
    EXPECT_EQ(parse_bytes("1.5G"), 3u << 29);
    EXPECT_EQ(parse_bytes("2GB"), std::uint64_t(2) << 30);
    EXPECT_EQ(parse_bytes("1T"), std::uint64_t(1) << 40);
    for (const char* bad :
         {"", "G", "lots", "-1G", "1.5", "1e9", "0x10", "4Q", "nanG", "inf", "9999999T", "1 G"})
        EXPECT_FALSE(parse_bytes(bad)) << bad;

    EXPECT_EQ(format_bytes(512), "512 bytes");
    EXPECT_EQ(format_bytes(4096), "4.0 KiB");
    EXPECT_EQ(format_bytes(64u << 20), "64 MiB");
    EXPECT_EQ(format_bytes(3u << 29), "1.5 GiB");
}

TEST(MemoryEstimate, ARenderBeyondTheLimitIsRefusedWithItsParts) {
    Scene scene;
    scene.settings.width = 16000;
    scene.settings.height = 12000;
    MemoryEstimate need;
    need.references = 1234567;
    need.acceleration = 1 << 20;
    need.film = std::uint64_t(14) << 30;
    const auto refusal =
        memory_refusal(scene, AccelKind::bvh, need, std::uint64_t(1) << 30, "--max-memory");
    ASSERT_TRUE(refusal);
    EXPECT_EQ(*refusal,
              "the render needs about 14 GiB of memory (the bvh 1.0 MiB for 1,234,567 primitives "
              "and triangles, the film 14 GiB for 16000x12000 pixels), more than the 1.0 GiB "
              "--max-memory allows; render fewer pixels, or set the limit with --max-memory SIZE");
    EXPECT_FALSE(memory_refusal(scene, AccelKind::bvh, need, std::uint64_t(15) << 30, "limit"));
    EXPECT_EQ(with_thousands(0), "0");
    EXPECT_EQ(with_thousands(999), "999");
    EXPECT_EQ(with_thousands(1000), "1,000");
}

TEST(MemoryEstimate, TheMachineHasSomeMemoryAvailable) {
    const auto available = available_memory();
    ASSERT_TRUE(available);  // Linux: /proc/meminfo
    EXPECT_GT(*available, std::uint64_t(16) << 20);
}

}  // namespace
}  // namespace glint
