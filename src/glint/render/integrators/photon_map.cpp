// The hash grid: photons counted into buckets by the hash of their cell, then placed by a prefix
// sum, a stable counting sort that keeps the photons of a bucket in the order they were traced.
#include "glint/render/integrators/photon_map.h"

#include <algorithm>
#include <cmath>

#include "glint/sampling/random.h"

namespace glint {

PhotonMap::PhotonMap(std::vector<Photon> photons, float radius) : radius_(radius) {
    // Twice as many buckets as photons (a power of two): few cells share one.
    std::size_t buckets = 1;
    while (buckets < 2 * photons.size()) buckets *= 2;
    starts_.assign(buckets + 1, 0);
    std::vector<std::size_t> bucket(photons.size());
    for (std::size_t i = 0; i < photons.size(); ++i) {
        const Point3 p = photons[i].position;
        bucket[i] = bucket_of(cell_of(p.x), cell_of(p.y), cell_of(p.z));
        ++starts_[bucket[i] + 1];
    }
    for (std::size_t b = 0; b < buckets; ++b) starts_[b + 1] += starts_[b];
    photons_.resize(photons.size());
    std::vector<std::uint32_t> next(starts_.begin(), starts_.end() - 1);
    for (std::size_t i = 0; i < photons.size(); ++i) photons_[next[bucket[i]]++] = photons[i];
}

// Clamped so that a coordinate far beyond the radius still has a cell (they share the last).
int PhotonMap::cell_of(float v) const {
    return int(std::clamp(std::floor(v / radius_), -1073741824.0f, 1073741824.0f));
}

std::size_t PhotonMap::bucket_of(int x, int y, int z) const {
    const std::uint64_t h = mix64(std::uint64_t(std::uint32_t(x)) * 0x9e3779b97f4a7c15ull ^
                                  std::uint64_t(std::uint32_t(y)) * 0xc2b2ae3d27d4eb4full ^
                                  std::uint64_t(std::uint32_t(z)) * 0x165667b19e3779f9ull);
    return std::size_t(h & (starts_.size() - 2));
}

}  // namespace glint
