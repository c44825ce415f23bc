// A render's counts (rays by kind, the bad samples) as bytes: in a resume file's state and in
// the results a rank of a cluster sends back.
#pragma once

#include "glint/render/byte_stream.h"
#include "glint/render/film/film.h"
#include "glint/render/ray_stats.h"

namespace glint {

inline void write_counts(ByteWriter& out, const RayStats& rays, const BadSamples& bad) {
    for (const std::uint64_t n : rays.traced) out.u64(n);
    out.u64(rays.primary_hits);
    out.u64(rays.particles);
    out.u64(rays.particles_seen);
    out.u64(rays.photons_stored);
    out.u64(rays.shadow_map_lookups);
    out.u64(bad.count);
    const SampleLocation first = bad.first.value_or(SampleLocation{});
    out.u8(bad.first ? 1 : 0);
    out.i32(first.x);
    out.i32(first.y);
    out.i32(first.sample);
}

// The bytes write_counts writes.
inline constexpr std::size_t kCountsSize = kRayKindCount * 8 + 5 * 8 + 8 + 1 + 3 * 4;

template <class Error>
void read_counts(ByteReader<Error>& in, RayStats& rays, BadSamples& bad) {
    for (std::uint64_t& n : rays.traced) n = in.u64();
    rays.primary_hits = in.u64();
    rays.particles = in.u64();
    rays.particles_seen = in.u64();
    rays.photons_stored = in.u64();
    rays.shadow_map_lookups = in.u64();
    bad.count = in.u64();
    const bool has_first = in.u8() != 0;
    SampleLocation first;
    first.x = in.i32();
    first.y = in.i32();
    first.sample = in.i32();
    bad.first.reset();
    if (has_first) bad.first = first;
}

}  // namespace glint
