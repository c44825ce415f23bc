// Which instructions the wide BVH's node and leaf tests run on: the best the CPU has, picked once
// at start up, and switchable so that tests and benchmarks can run every path on one machine.
#pragma once

#include <atomic>
#include <cstdint>
#include <string_view>

namespace glint {

// Every path gives bit-identical results; they differ only in speed.
enum class SimdPath : std::uint8_t {
    scalar,  // portable C++, one box at a time; the only path off x86-64
    sse,     // four boxes at once in 128-bit registers (every x86-64 CPU has SSE2)
    // Eight boxes at once in 256-bit registers, for CPUs that report AVX2; also on CPUs with
    // AVX-512, where the same kernels EVEX-encoded were slower on 71 of the 75 rows of the
    // Embree benchmark (0.81-0.99x; bench/README.md).
    avx2,
};

// Every path, slowest first (for tests and benchmarks that try each one this CPU supports).
inline constexpr SimdPath kSimdPaths[] = {SimdPath::scalar, SimdPath::sse, SimdPath::avx2};

std::string_view simd_path_name(SimdPath path);

// Whether this build and this CPU can run the path (the OS must save AVX registers for avx2).
bool simd_path_supported(SimdPath path);
// The fastest supported path.
SimdPath best_simd_path();

namespace detail {
// Starts as best_simd_path(); scalar (zero) during static initialisation, which is still exact.
extern std::atomic<SimdPath> simd_path_in_use;
}  // namespace detail

// The path that traversals use now. Read once per ray.
inline SimdPath simd_path() { return detail::simd_path_in_use.load(std::memory_order_relaxed); }

// Chooses the path for traversals that start from now on; false (and no change) when the path is
// not supported. Meant for tests and benchmarks, not for switching while rays are in flight.
bool set_simd_path(SimdPath path);

}  // namespace glint
