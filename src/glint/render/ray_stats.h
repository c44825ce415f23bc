// Counts of the rays a render traced, by kind, as the lecture notes name them.
#pragma once

#include <cstdint>

namespace glint {

struct RayStats {
    std::uint64_t primary = 0;       // eye rays
    std::uint64_t primary_hits = 0;  // eye rays that hit something
    std::uint64_t shadow = 0;        // shadow feelers (each segment through transparent objects)
    std::uint64_t reflected = 0;
    std::uint64_t refracted = 0;

    std::uint64_t total() const { return primary + shadow + reflected + refracted; }

    RayStats& operator+=(const RayStats& o) {
        primary += o.primary;
        primary_hits += o.primary_hits;
        shadow += o.shadow;
        reflected += o.reflected;
        refracted += o.refracted;
        return *this;
    }
    bool operator==(const RayStats&) const = default;
};

}  // namespace glint
