// Eye rays of a render's packets, made as the render loop makes them: blocks of 4 x 2 pixels at one
// sample index, with the distributed benchmark's thin lens and Sobol sampler at 16 samples a
// pixel. Each lane's ray made from start to end, lane after lane (the reference), against the
// packet made in phases (every lane's numbers, then every aperture point, then every ray), which
// lets the processor overlap the lanes' chains of dependent instructions. Both make the same rays,
// bit for bit. Ratios are recorded in bench/README.md.
#include <benchmark/benchmark.h>

#include <array>
#include <optional>

#include "glint/camera/camera.h"
#include "glint/math/ray.h"
#include "glint/render/eye_sample.h"
#include "glint/sampling/sampler.h"

namespace glint {
namespace {

constexpr int kWidth = 480, kHeight = 270, kSpp = 16;
constexpr int kBlockWidth = 4, kBlockHeight = kRayPacketSize / kBlockWidth;
// The 64 x 32 pixels from (208, 120), near the image's centre.
constexpr int kX0 = 208, kY0 = 120, kTileWidth = 64, kTileHeight = 32;

// bench/distributed_vs_povray/scene.yaml's camera.
Camera benchmark_camera() {
    CameraSpec spec;
    spec.from = {0, 2.3f, -8.5f};
    spec.at = {0, 0.9f, 0};
    spec.fov = 38;
    spec.lens.radius = 0.12f;
    spec.lens.focus_distance = 8;
    return Camera(spec, kWidth, kHeight);
}

// Calls make(lanes, streams, count, rays) for every block of the tile at every sample index.
template <typename Make>
void for_each_block(const Sampler& sampler, Make&& make) {
    for (int y0 = kY0; y0 < kY0 + kTileHeight; y0 += kBlockHeight)
        for (int x0 = kX0; x0 < kX0 + kTileWidth; x0 += kBlockWidth) {
            std::array<std::optional<PixelPatterns>, kRayPacketSize> patterns;
            std::array<std::array<int, 2>, kRayPacketSize> at;
            std::size_t count = 0;
            for (int y = y0; y < y0 + kBlockHeight; ++y)
                for (int x = x0; x < x0 + kBlockWidth; ++x) {
                    patterns[count].emplace(sampler, std::uint64_t(y) * kWidth + std::uint64_t(x));
                    at[count++] = {x, y};
                }
            for (int s = 0; s < kSpp; ++s) {
                std::array<std::optional<SampleStream>, kRayPacketSize> streams;
                for (std::size_t i = 0; i < count; ++i)
                    streams[i].emplace(*patterns[i], std::uint32_t(s));
                std::array<Ray, kRayPacketSize> rays;
                make(at, streams, count, rays);
                benchmark::DoNotOptimize(rays);
            }
        }
}

void BM_EyeRaysLaneByLaneReference(benchmark::State& state) {
    const Camera camera = benchmark_camera();
    const Sampler sampler(SamplerKind::sobol, kSpp, 1);
    for (auto _ : state)
        for_each_block(sampler, [&](const auto& at, const auto& streams, std::size_t count,
                                    std::array<Ray, kRayPacketSize>& rays) {
            for (std::size_t i = 0; i < count; ++i)
                rays[i] = eye_sample(camera, *streams[i], at[i][0], at[i][1]).ray;
        });
    state.SetItemsProcessed(state.iterations() * kTileWidth * kTileHeight * kSpp);
}

void BM_EyeRaysInPhases(benchmark::State& state) {
    const Camera camera = benchmark_camera();
    const Sampler sampler(SamplerKind::sobol, kSpp, 1);
    for (auto _ : state)
        for_each_block(sampler, [&](const auto& at, const auto& streams, std::size_t count,
                                    std::array<Ray, kRayPacketSize>& rays) {
            std::array<EyeNumbers, kRayPacketSize> numbers;
            for (std::size_t i = 0; i < count; ++i) numbers[i] = eye_numbers(camera, *streams[i]);
            for (std::size_t i = 0; i < count; ++i) find_aperture_point(camera, numbers[i]);
            for (std::size_t i = 0; i < count; ++i)
                rays[i] = eye_sample(camera, numbers[i], at[i][0], at[i][1]).ray;
        });
    state.SetItemsProcessed(state.iterations() * kTileWidth * kTileHeight * kSpp);
}

BENCHMARK(BM_EyeRaysLaneByLaneReference);
BENCHMARK(BM_EyeRaysInPhases);

}  // namespace
}  // namespace glint

BENCHMARK_MAIN();
