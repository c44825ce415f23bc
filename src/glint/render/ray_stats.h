// Counts of the rays a render traced, by kind, as the lecture notes name them. A new kind of ray
// (an integrator's own) is one more RayKind and its name: the summary and the statistics file
// list every kind.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace glint {

enum class RayKind : std::uint8_t {
    primary,    // eye rays, through the pixel (and the lens)
    shadow,     // shadow feelers, towards a light or a point on one (each segment through
                // transparent objects counts)
    reflected,  // mirror or glossy reflection
    refracted,  // refraction or translucency
    diffuse,    // scattered by the diffuse part of a material, or its highlight (path tracing)
    particle,   // a particle's path from a light (light tracing), its every segment
};
inline constexpr std::size_t kRayKindCount = 6;
// Names by RayKind, as the summary and the JSON statistics show them.
inline constexpr std::array<std::string_view, kRayKindCount> kRayKindNames = {
    "primary", "shadow", "reflected", "refracted", "diffuse", "particle"};

struct RayStats {
    std::array<std::uint64_t, kRayKindCount> traced{};  // by RayKind
    std::uint64_t primary_hits = 0;                     // eye rays that hit something
    // Particles that left the lights, and how many of them were seen by the eye (the notes'
    // "most rays will never even get close to the eye", counted).
    std::uint64_t particles = 0, particles_seen = 0;
    // The photon integrator's photons that came to rest in its maps (it counts those it
    // emitted as particles).
    std::uint64_t photons_stored = 0;
    // Shadows looked up in shadow maps instead of traced as feelers (shadows: map).
    std::uint64_t shadow_map_lookups = 0;

    void count(RayKind kind) { ++traced[std::size_t(kind)]; }
    std::uint64_t operator[](RayKind kind) const { return traced[std::size_t(kind)]; }

    std::uint64_t total() const {
        std::uint64_t sum = 0;
        for (const std::uint64_t n : traced) sum += n;
        return sum;
    }

    RayStats& operator+=(const RayStats& o) {
        for (std::size_t i = 0; i < kRayKindCount; ++i) traced[i] += o.traced[i];
        primary_hits += o.primary_hits;
        particles += o.particles;
        particles_seen += o.particles_seen;
        photons_stored += o.photons_stored;
        shadow_map_lookups += o.shadow_map_lookups;
        return *this;
    }
    bool operator==(const RayStats&) const = default;
};

}  // namespace glint
