// How a point, and a normal, interpolated across a triangle change with the triangle's texture
// coordinates: dp/du and dp/dv (and dn/du, dn/dv) from the corners' values and uvs.
#pragma once

#include <array>
#include <cmath>

#include "glint/math/vector.h"

namespace glint {

struct UvDerivatives {
    Vector3 du, dv;
};

// f0 + (f1 - f0) b1 + (f2 - f0) b2 over the triangle is linear in uv: solves
//   f0 - f2 = du (u0 - u2) + dv (v0 - v2),  f1 - f2 = du (u1 - u2) + dv (v1 - v2).
// Corners whose uvs span no area (all equal, or on a line) are read with the barycentric
// coordinates (0, 0), (1, 0), (0, 1) instead, as the uv of a mesh without uvs.
inline UvDerivatives uv_derivatives(const std::array<Vector3, 3>& f,
                                    const std::array<Point2, 3>& uv) {
    auto solve = [&](Point2 a, Point2 b, Point2 c) {
        const float du02 = a.x - c.x, dv02 = a.y - c.y, du12 = b.x - c.x, dv12 = b.y - c.y;
        const float det = du02 * dv12 - dv02 * du12;
        return std::pair{det, UvDerivatives{((f[0] - f[2]) * dv12 - (f[1] - f[2]) * dv02) / det,
                                            ((f[1] - f[2]) * du02 - (f[0] - f[2]) * du12) / det}};
    };
    const auto [det, d] = solve(uv[0], uv[1], uv[2]);
    if (std::abs(det) > 1e-12f && is_finite(d.du) && is_finite(d.dv)) return d;
    return solve({0, 0}, {1, 0}, {0, 1}).second;
}

}  // namespace glint
