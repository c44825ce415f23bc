// Filling triangle blocks, and the SIMD test's exact fallback. The area check here rounds as
// watertight_triangle.cpp's (no fused multiply-adds anywhere in glint: CMakeLists.txt).
#include "glint/geometry/triangle_block.h"

#include <limits>

namespace glint {

TriangleBlock empty_triangle_block() {
    TriangleBlock block;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    for (auto& corner : block.v)
        for (auto& axis : corner)
            for (float& x : axis) x = nan;
    for (std::uint32_t& id : block.id) id = kNoTriangle;
    return block;
}

void set_block_lane(TriangleBlock& block, int lane, Point3 v0, Point3 v1, Point3 v2,
                    std::uint32_t id) {
    // intersect_watertight rejects such a triangle for every ray, after the same computation.
    const Vector3 normal = cross(v1 - v0, v2 - v0);
    if (normal.x == 0 && normal.y == 0 && normal.z == 0) return;
    const Point3 corners[3] = {v0, v1, v2};
    for (int c = 0; c < 3; ++c) {
        block.v[c][0][lane] = corners[c].x;
        block.v[c][1][lane] = corners[c].y;
        block.v[c][2][lane] = corners[c].z;
    }
    block.id[lane] = id;
}

#ifdef GLINT_TRIANGLE_BLOCK_HAS_SIMD
namespace block_simd {

namespace {

// edge_function of watertight_triangle.cpp for a zero float result: p -> q in the sheared plane.
float exact_edge(float px, float py, float qx, float qy) {
    return float(double(qx) * double(py) - double(qy) * double(px));
}

}  // namespace

Float4 exact_zero_edge(unsigned lanes, const TriangleBlock& b, const Ray4& r, Float4 w, int edge) {
    const std::size_t kx = r.kx / sizeof(Float4), ky = r.ky / sizeof(Float4),
                      kz = r.kz / sizeof(Float4);
    // The edge runs from corner edge + 1 to corner edge + 2, as in candidates().
    const int p = (edge + 1) % 3, q = (edge + 2) % 3;
    for (; lanes != 0; lanes &= lanes - 1) {
        const int k = __builtin_ctz(lanes);
        // Both corners sheared as candidates() shears them, one float operation at a time.
        float x[2], y[2];
        for (int i = 0; i < 2; ++i) {
            const int c = i == 0 ? p : q;
            const float z = b.v[c][kz][k] - r.oz[0];
            x[i] = (b.v[c][kx][k] - r.ox[0]) - r.sx[0] * z;
            y[i] = (b.v[c][ky][k] - r.oy[0]) - r.sy[0] * z;
        }
        w[k] = exact_edge(x[0], y[0], x[1], y[1]);
    }
    return w;
}

}  // namespace block_simd
#endif

}  // namespace glint
