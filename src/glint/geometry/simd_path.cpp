// The CPU check behind SimdPath: GCC's __builtin_cpu_supports, which also checks that the OS saves
// the AVX registers.
#include "glint/geometry/simd_path.h"

namespace glint {

namespace detail {
std::atomic<SimdPath> simd_path_in_use{best_simd_path()};
}  // namespace detail

std::string_view simd_path_name(SimdPath path) {
    switch (path) {
        case SimdPath::scalar:
            return "scalar";
        case SimdPath::sse:
            return "sse";
        case SimdPath::avx2:
            return "avx2";
    }
    return "unknown";
}

bool simd_path_supported(SimdPath path) {
#if defined(__x86_64__) && defined(__GNUC__)
    // Static initialisers run before libgcc has filled in its CPU model; ask it to now.
    __builtin_cpu_init();
    switch (path) {
        case SimdPath::scalar:
        case SimdPath::sse:
            return true;
        case SimdPath::avx2:
            return __builtin_cpu_supports("avx2");
    }
    return false;
#else
    return path == SimdPath::scalar;
#endif
}

SimdPath best_simd_path() {
    if (simd_path_supported(SimdPath::avx2)) return SimdPath::avx2;
    if (simd_path_supported(SimdPath::sse)) return SimdPath::sse;
    return SimdPath::scalar;
}

bool set_simd_path(SimdPath path) {
    if (!simd_path_supported(path)) return false;
    detail::simd_path_in_use.store(path, std::memory_order_relaxed);
    return true;
}

}  // namespace glint
