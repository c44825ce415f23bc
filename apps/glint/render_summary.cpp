// The summary a finished render prints: the image, its size and samples, the time, and the rays
// of each kind.
#include "render_summary.h"

#include <cstdio>

#include "glint/render/memory_estimate.h"

namespace glint::cli {

void print_summary(const std::string& output, const RenderSettings& s, const RenderResult& r,
                   const std::string& note) {
    const std::string before = note.empty() ? "" : note + "; ";
    const RayStats& rays = r.rays;
    const double mrays = r.seconds > 0 ? double(rays.total()) / r.seconds / 1e6 : 0;
    if (s.adaptive) {
        // Every pixel's samples are its eye rays.
        const double pixels = double(s.width) * s.height;
        std::printf("glint: wrote %s (%s%dx%d, adaptive: %.1f of at most %d spp) in %.2f s\n",
                    output.c_str(), before.c_str(), s.width, s.height,
                    double(r.rays.traced[std::size_t(RayKind::primary)]) / pixels,
                    s.samples_per_pixel, r.seconds);
    } else {
        std::printf("glint: wrote %s (%s%dx%d, %d spp) in %.2f s\n", output.c_str(), before.c_str(),
                    s.width, s.height, s.samples_per_pixel, r.seconds);
    }
    std::printf("  rays       %15s  %.2f Mrays/s\n", with_thousands(rays.total()).c_str(), mrays);
    for (std::size_t kind = 0; kind < kRayKindCount; ++kind) {
        // The notes' four kinds always; the others when an integrator traced them.
        if (kind > std::size_t(RayKind::refracted) && rays.traced[kind] == 0) continue;
        std::printf("  %-10s %15s", std::string(kRayKindNames[kind]).c_str(),
                    with_thousands(rays.traced[kind]).c_str());
        if (RayKind(kind) == RayKind::primary)
            std::printf("  (%s hit)", with_thousands(rays.primary_hits).c_str());
        std::printf("\n");
    }
    if (rays.shadow_map_lookups > 0)
        std::printf("  shadow-map lookups %7s  (in place of shadow feelers)\n",
                    with_thousands(rays.shadow_map_lookups).c_str());
    if (rays.photons_stored > 0)
        std::printf("  photons    %15s  (%s stored)\n", with_thousands(rays.particles).c_str(),
                    with_thousands(rays.photons_stored).c_str());
    else if (rays.particles > 0)
        std::printf("  particles  %15s  (%s, %.2g%%, reached the eye)\n",
                    with_thousands(rays.particles).c_str(),
                    with_thousands(rays.particles_seen).c_str(),
                    100.0 * double(rays.particles_seen) / double(rays.particles));
}

}  // namespace glint::cli
