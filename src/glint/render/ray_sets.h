// Fixed sets of rays for measuring acceleration structures on identical work: coherent eye rays,
// incoherent rays leaving the surfaces they hit, and shadow feelers from there towards a light.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

#include "glint/math/interval.h"
#include "glint/math/ray.h"
#include "glint/render/world.h"

namespace glint {

enum class RayQuery { closest_hit, occluded };

struct RaySet {
    std::string_view name;  // "primary", "incoherent" or "shadow"
    RayQuery query = RayQuery::closest_hit;
    std::uint32_t mask = kVisibleToCameraRays;  // the ray mask of every query
    std::vector<Ray> rays;
    std::vector<Interval> ranges;  // one per ray; empty when every range is [0, inf)

    Interval range(std::size_t i) const { return ranges.empty() ? Interval{} : ranges[i]; }
};

struct RaySets {
    int width = 0, height = 0;       // the image the primary rays cover, one ray a pixel
    std::size_t surface_points = 0;  // primary rays that hit: where the other two sets start
    std::vector<RaySet> sets;        // primary, incoherent, shadow; equally many rays each
};

// Up to this many rays a set (32 bytes a ray and range).
inline constexpr std::size_t kMaxRaysPerSet = std::size_t(1) << 24;

// A pure function of the world, count and seed (glint's counter-based random numbers):
// - primary: one eye ray through the centre of each pixel in scanline order, the scene's image
//   scaled (aspect kept) to about `count` pixels;
// - incoherent: from the surface points the primary rays hit (found once with the world's own
//   structure, cycled through in scanline order), a uniformly random direction on the hemisphere
//   on the side the eye ray came from, origin offset as World::spawn_ray does;
// - shadow: from the same points towards the scene's first light (or, without lights, a point
//   above the scene's bounds), the range ending at the light, with the shadow-ray mask.
// The last two are empty when no primary ray hits anything. count is clamped to
// [1, kMaxRaysPerSet].
RaySets make_ray_sets(const World& world, std::size_t count, std::uint64_t seed = 0);

// The order in which packets of kRayPacketSize rays take a set's rays, eight after eight: the
// primary rays in tiles of 4 x 2 pixels (the render loop's packets), the others as they are
// (feelers and bounces from the surface points of neighbouring pixels along a row).
RaySet in_packet_order(const RaySet& set, int width, int height);

}  // namespace glint
