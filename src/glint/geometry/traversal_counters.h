// Counts of traversal work, for the nodes and primitives output variables: acceleration-structure
// nodes (or grid cells) visited and primitives tested, per thread. Compiled in only when glint is
// configured with -DGLINT_TRAVERSAL_COUNTERS=ON: an increment in the innermost loops costs every
// render time, and only the cost images need them. Without it the counts stay 0.
#pragma once

#include <cstdint>

namespace glint {

#ifdef GLINT_TRAVERSAL_COUNTERS
inline constexpr bool kCountTraversal = true;
#else
inline constexpr bool kCountTraversal = false;
#endif

struct TraversalCounters {
    std::uint64_t nodes = 0;       // interior nodes (or grid cells) visited
    std::uint64_t primitives = 0;  // primitives (triangles, spheres, shapes) tested for a hit
};

// This thread's counts so far; the render loop takes differences around each sample.
inline thread_local TraversalCounters traversal_counters;

inline void count_nodes(std::uint64_t n = 1) {
    if constexpr (kCountTraversal) traversal_counters.nodes += n;
}
inline void count_primitives(std::uint64_t n = 1) {
    if constexpr (kCountTraversal) traversal_counters.primitives += n;
}

}  // namespace glint
