// Measuring an acceleration structure on fixed ray sets: build time, rays per second at a given
// thread count, and memory per primitive. `glint bench` reports these figures.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>

#include "glint/accel/aggregate.h"
#include "glint/accel/make_aggregate.h"
#include "glint/render/ray_sets.h"

namespace glint {

struct BuildMeasure {
    std::unique_ptr<Aggregate> aggregate;
    double seconds = 0;  // wall time of make_aggregate
};

// Builds on `threads` worker threads (a oneTBB arena of that size; Embree builds in it too).
BuildMeasure measure_build(AccelKind kind, std::span<const Primitive> primitives, int threads);

struct TraceMeasure {
    double seconds = 0;      // the best (shortest) wall time of the repetitions
    std::uint64_t hits = 0;  // rays that hit (closest hit) or were blocked (occluded)

    double mrays_per_second(std::size_t rays) const {
        return seconds > 0 ? double(rays) / seconds / 1e6 : 0;
    }
};

// Traces every ray of the set through the aggregate (closest hit or occluded, as the set says),
// in chunks of consecutive rays spread over `threads` worker threads, `repetitions` times; with
// `packets`, kRayPacketSize consecutive rays at a time (Aggregate::intersect_packet and
// occluded_packet; in_packet_order gives the order).
TraceMeasure measure_trace(const Aggregate& aggregate, const RaySet& set, int threads,
                           int repetitions = 3, bool packets = false);

// The primitives for figures per primitive: a TriangleMesh counts its triangles, so that bytes
// per primitive compare with structures (Embree) that hold the triangles themselves.
std::size_t triangle_counted_primitives(std::span<const Primitive> primitives);

// The memory of the BVHs inside the meshes counted above (each shared mesh once): part of what a
// glint structure needs to trace meshes, which Embree replaces with its own.
std::size_t mesh_bvh_bytes(std::span<const Primitive> primitives);

}  // namespace glint
