// Values that render tests compare against, computed another way: the penumbra of a disk light
// by numerical integration over it, and the root mean square difference of two images.
#pragma once

#include <cmath>

#include "glint/image/image.h"
#include "glint/math/constants.h"

namespace glint::testing {

// A disk light of radius 1 at height 4 over the origin facing down, an occluding disk of radius
// 0.5 at height 2, a white floor (kd 1, IL 1): the exact local term at floor point (x, 0, 0) is
// the mean over the light's area of visible(p, q) (N.L(q)). Integrated on a fine polar grid.
inline double penumbra_by_integration(float x) {
    const int rings = 400, sectors = 400;
    double sum = 0, area = 0;
    for (int i = 0; i < rings; ++i)
        for (int j = 0; j < sectors; ++j) {
            const double r = (i + 0.5) / rings, phi = 2 * kPi * (j + 0.5) / sectors;
            const double qx = r * std::cos(phi), qz = r * std::sin(phi);
            const double dx = qx - x, dy = 4, dz = qz;
            const double d = std::sqrt(dx * dx + dy * dy + dz * dz);
            // Where the segment from p = (x, 0, 0) to q crosses y = 2: halfway.
            const double mx = x + dx / 2, mz = dz / 2;
            const bool blocked = mx * mx + mz * mz < 0.25;
            const double weight = r;  // area element r dr dphi
            area += weight;
            if (!blocked) sum += weight * dy / d;
        }
    return sum / area;
}

// The root mean square difference of two images of one size, over their channels.
inline float rms_difference(const Image& a, const Image& b) {
    double sum = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        const Color d = a.pixels[i] - b.pixels[i];
        sum += double(d.r * d.r + d.g * d.g + d.b * d.b) / 3;
    }
    return float(std::sqrt(sum / double(a.pixels.size())));
}

}  // namespace glint::testing
