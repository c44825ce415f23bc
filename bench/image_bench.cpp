// Writing an 8-bit image: quantising linear colours to dithered sRGB bytes (quantize.h) and
// encoding them as PNG (png_io.h), the part of `glint render`'s time after the render. The image
// is a render's kind of picture: smooth shading with a few per cent of Monte Carlo noise, and
// highlights above 1. Ratios are in bench/README.md.
#include <benchmark/benchmark.h>
#include <png.h>
#include <tbb/global_control.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "glint/image/png_io.h"
#include "glint/image/quantize.h"
#include "glint/sampling/random.h"

namespace glint {
namespace {

Image rendered_like(int width, int height) {
    Image image(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const float u = float(x) / float(width), v = float(y) / float(height);
            const float shade = 0.02f + 1.2f * u * u * (1 - v) + 0.3f * std::sin(9 * u * v);
            const std::uint64_t pixel = (std::uint64_t(y) << 32) | std::uint64_t(x);
            Color c{shade, 0.8f * shade, 0.5f * shade + 0.05f};
            for (int k = 0; k < 3; ++k) {
                const float noise = 1 + 0.1f * (random_float(pixel, 0, std::uint64_t(k), 7) - 0.5f);
                (k == 0 ? c.r : k == 1 ? c.g : c.b) *= noise;
            }
            image.at(x, y) = c;
        }
    return image;
}

const Image& subject() {
    static const Image image = rendered_like(800, 600);
    return image;
}

// The reference: one value at a time through quantize_srgb8(float, x, y, channel), one thread.
void BM_QuantizeOneValueAtATime(benchmark::State& state) {
    const Image& image = subject();
    std::vector<std::uint8_t> bytes(image.pixels.size() * 3);
    for (auto _ : state) {
        std::size_t i = 0;
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x) {
                const Color& c = image.at(x, y);
                bytes[i++] = quantize_srgb8(c.r, x, y, 0);
                bytes[i++] = quantize_srgb8(c.g, x, y, 1);
                bytes[i++] = quantize_srgb8(c.b, x, y, 2);
            }
        benchmark::DoNotOptimize(bytes.data());
    }
    state.SetItemsProcessed(state.iterations() * std::int64_t(image.pixels.size()));
}
BENCHMARK(BM_QuantizeOneValueAtATime)->Unit(benchmark::kMillisecond);

// The whole image, as the writers quantise it; the argument is the number of threads.
void BM_QuantizeImage(benchmark::State& state) {
    tbb::global_control threads(tbb::global_control::max_allowed_parallelism,
                                std::size_t(state.range(0)));
    const Image& image = subject();
    for (auto _ : state) benchmark::DoNotOptimize(quantize_srgb8(image));
    state.SetItemsProcessed(state.iterations() * std::int64_t(image.pixels.size()));
}
BENCHMARK(BM_QuantizeImage)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

// The whole PNG in memory: quantising and encoding, as write_png does; the argument is the
// number of threads.
void BM_PngBytes(benchmark::State& state) {
    tbb::global_control threads(tbb::global_control::max_allowed_parallelism,
                                std::size_t(state.range(0)));
    const Image& image = subject();
    std::size_t size = 0;
    for (auto _ : state) {
        const std::string png = png_bytes(image);
        size = png.size();
        benchmark::DoNotOptimize(png.data());
    }
    state.counters["bytes_per_pixel"] = double(size) / double(image.pixels.size());
}
BENCHMARK(BM_PngBytes)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

// The same, stored without compression (glint-serve's frames in flight); two threads.
void BM_PngBytesStored(benchmark::State& state) {
    const Image& image = subject();
    for (auto _ : state) benchmark::DoNotOptimize(png_bytes(image, PngDeflate::stored).data());
}
BENCHMARK(BM_PngBytesStored)->Unit(benchmark::kMillisecond);

// The reference encoder: how glint wrote PNGs before, libpng compressing the same bytes with
// zlib's fastest level and its own choice of filter for each row; one thread.
void append_to_string(png_structp png, png_bytep data, png_size_t count) {
    static_cast<std::string*>(png_get_io_ptr(png))->append(reinterpret_cast<char*>(data), count);
}

void BM_PngBytesThroughLibpngsZlib(benchmark::State& state) {
    tbb::global_control threads(tbb::global_control::max_allowed_parallelism, 1);
    const Image& image = subject();
    std::size_t size = 0;
    for (auto _ : state) {
        std::vector<std::uint8_t> bytes = quantize_srgb8(image);
        std::vector<png_bytep> rows(std::size_t(image.height));
        for (std::size_t y = 0; y < rows.size(); ++y)
            rows[y] = bytes.data() + y * std::size_t(image.width) * 3;
        std::string png;
        png_structp p = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
        png_infop info = png_create_info_struct(p);
        png_set_write_fn(p, &png, append_to_string, nullptr);
        png_set_IHDR(p, info, png_uint_32(image.width), png_uint_32(image.height), 8,
                     PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                     PNG_FILTER_TYPE_DEFAULT);
        png_set_sRGB_gAMA_and_cHRM(p, info, PNG_sRGB_INTENT_PERCEPTUAL);
        png_set_compression_level(p, 1);
        png_write_info(p, info);
        png_write_image(p, rows.data());
        png_write_end(p, info);
        png_destroy_write_struct(&p, &info);
        size = png.size();
        benchmark::DoNotOptimize(png.data());
    }
    state.counters["bytes_per_pixel"] = double(size) / double(image.pixels.size());
}
BENCHMARK(BM_PngBytesThroughLibpngsZlib)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace glint

BENCHMARK_MAIN();
