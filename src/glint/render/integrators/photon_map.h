// A pass's photons, where the photon integrator's particles came to rest on surfaces that are
// not delta, in a hash grid of cells as wide as the gathering radius: the photons within the
// radius of a point are those of the 27 cells around its own.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "glint/math/color.h"
#include "glint/math/vector.h"

namespace glint {

struct Photon {
    Point3 position;
    Vector3 from;    // unit, towards where it came from (wi at the surface)
    Normal3 normal;  // the surface's geometric normal there, on the side the photon arrived on
    Color power;     // the flux it carries, before dividing by the photons a pass
};

class PhotonMap {
public:
    PhotonMap() = default;
    // Over `photons` (taken), for gathering within `radius` (> 0).
    PhotonMap(std::vector<Photon> photons, float radius);

    float radius() const { return radius_; }
    std::size_t size() const { return photons_.size(); }

    // Calls visit(photon) for every photon within the radius of p, in a fixed order.
    template <class Visit>
    void for_each_near(Point3 p, const Visit& visit) const {
        if (photons_.empty()) return;
        const float r2 = radius_ * radius_;
        const int cx = cell_of(p.x), cy = cell_of(p.y), cz = cell_of(p.z);
        // Two of the cells may share a bucket: each bucket is visited once.
        std::size_t visited[27];
        int visits = 0;
        for (int dz = -1; dz <= 1; ++dz)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const std::size_t bucket = bucket_of(cx + dx, cy + dy, cz + dz);
                    bool seen = false;
                    for (int v = 0; v < visits; ++v) seen |= visited[v] == bucket;
                    if (seen) continue;
                    visited[visits++] = bucket;
                    for (std::uint32_t i = starts_[bucket]; i < starts_[bucket + 1]; ++i) {
                        const Photon& photon = photons_[i];
                        if (length_squared(photon.position - p) <= r2) visit(photon);
                    }
                }
    }

private:
    int cell_of(float v) const;
    std::size_t bucket_of(int x, int y, int z) const;

    float radius_ = 1;
    std::vector<Photon> photons_;        // sorted by bucket
    std::vector<std::uint32_t> starts_;  // bucket b holds photons_[starts_[b], starts_[b + 1])
};

}  // namespace glint
