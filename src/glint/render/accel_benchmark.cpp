// Timing builds and ray sets on a fixed number of threads.
#include "glint/render/accel_benchmark.h"

#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <chrono>
#include <optional>
#include <unordered_set>

#include "glint/accel/mesh_bvh.h"

namespace glint {

namespace {

// Rays a task: large enough that scheduling costs nothing next to tracing, small enough that
// two threads share even the smallest set; a whole number of packets.
constexpr std::size_t kChunk = 1024;

// Runs f with `threads` worker threads; TBB's cap at the core count is lifted for the run.
template <typename F>
void on_threads(int threads, F&& f) {
    threads = std::max(threads, 1);
    std::optional<tbb::global_control> allow;
    if (threads > tbb::this_task_arena::max_concurrency())
        allow.emplace(tbb::global_control::max_allowed_parallelism, threads);
    tbb::task_arena arena(threads);
    arena.execute(f);
}

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The hits of rays [begin, end) of the set, kRayPacketSize at a time.
std::uint64_t trace_packets(const Aggregate& aggregate, const RaySet& set, std::size_t begin,
                            std::size_t end) {
    std::uint64_t hits = 0;
    std::array<Interval, kRayPacketSize> ranges;
    std::array<std::optional<Hit>, kRayPacketSize> found;
    for (std::size_t first = begin; first < end; first += kRayPacketSize) {
        const std::size_t n = std::min(end - first, std::size_t(kRayPacketSize));
        const std::span<const Ray> rays(set.rays.data() + first, n);
        if (set.query == RayQuery::closest_hit) {
            // Closest-hit sets share the range [0, inf) (ray_sets.h).
            aggregate.intersect_packet(rays, set.range(first), set.mask, found.data());
            for (std::size_t i = 0; i < n; ++i) hits += found[i].has_value();
        } else {
            for (std::size_t i = 0; i < n; ++i) ranges[i] = set.range(first + i);
            hits += std::uint64_t(
                std::popcount(aggregate.occluded_packet(rays, ranges.data(), set.mask)));
        }
    }
    return hits;
}

std::uint64_t trace_once(const Aggregate& aggregate, const RaySet& set, bool packets) {
    std::atomic<std::uint64_t> hits{0};
    tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, set.rays.size(), kChunk),
        [&](const tbb::blocked_range<std::size_t>& range) {
            if (packets) {
                hits += trace_packets(aggregate, set, range.begin(), range.end());
                return;
            }
            std::uint64_t chunk_hits = 0;
            for (std::size_t i = range.begin(); i != range.end(); ++i) {
                if (set.query == RayQuery::closest_hit) {
                    chunk_hits += aggregate.intersect(set.rays[i], set.range(i), set.mask) ? 1 : 0;
                } else {
                    chunk_hits += aggregate.occluded(set.rays[i], set.range(i), set.mask) ? 1 : 0;
                }
            }
            hits += chunk_hits;
        },
        tbb::simple_partitioner());
    return hits;
}

}  // namespace

BuildMeasure measure_build(AccelKind kind, std::span<const Primitive> primitives, int threads) {
    BuildMeasure out;
    on_threads(threads, [&] {
        const auto start = std::chrono::steady_clock::now();
        out.aggregate = make_aggregate(kind, primitives);
        out.seconds = seconds_since(start);
    });
    return out;
}

TraceMeasure measure_trace(const Aggregate& aggregate, const RaySet& set, int threads,
                           int repetitions, bool packets) {
    TraceMeasure best;
    on_threads(threads, [&] {
        for (int r = 0; r < std::max(repetitions, 1); ++r) {
            const auto start = std::chrono::steady_clock::now();
            const std::uint64_t hits = trace_once(aggregate, set, packets);
            const double seconds = seconds_since(start);
            if (r == 0 || seconds < best.seconds) best.seconds = seconds;
            best.hits = hits;  // the same every time: the structures are deterministic
        }
    });
    return best;
}

std::size_t triangle_counted_primitives(std::span<const Primitive> primitives) {
    std::size_t n = 0;
    for (const Primitive& p : primitives) {
        const auto* mesh = std::get_if<TriangleMesh>(&p.shape);
        n += mesh ? mesh->data->triangles.size() : 1;
    }
    return n;
}

std::size_t mesh_bvh_bytes(std::span<const Primitive> primitives) {
    std::unordered_set<const MeshData*> seen;
    std::size_t bytes = 0;
    for (const Primitive& p : primitives) {
        const auto* mesh = std::get_if<TriangleMesh>(&p.shape);
        if (!mesh || !seen.insert(mesh->data.get()).second) continue;
        if (const auto* bvh = dynamic_cast<const MeshBvh*>(mesh->accelerator.get()))
            bytes += bvh->tree().memory_bytes();
    }
    return bytes;
}

}  // namespace glint
