// The crossing-count test of point_inside(): repeated nearest-hit queries along three rays.
#include "glint/geometry/point_inside.h"

#include <algorithm>
#include <cmath>

namespace glint {

namespace {

// More crossings than this along one ray (a fractal's many shells) stop the count; the parity
// so far stands.
constexpr int kMaxCrossings = 1024;

int crossings(const Shape& shape, Point3 p, Vector3 direction, float step) {
    const Ray ray{p, normalize(direction)};
    int count = 0;
    float t_min = 0;
    for (; count < kMaxCrossings; ++count) {
        const std::optional<ShapeHit> hit = intersect(shape, ray, {t_min, kInfinity});
        if (!hit) break;
        // Past the hit, so that the same surface is not found again.
        t_min = std::max(hit->t + step, std::nextafter(hit->t, kInfinity));
    }
    return count;
}

}  // namespace

std::optional<bool> point_inside(const Shape& shape, Point3 p) {
    if (!is_solid(shape)) return std::nullopt;
    const Bounds3 b = bounds(shape);
    if (!b.is_finite()) return std::nullopt;
    if (!b.contains(p)) return false;
    // A millionth of the shape's size: far below any feature a scene models, far above float
    // rounding of t.
    const float step = 1e-6f * length(b.diagonal());
    // Directions along no axis and in no symmetry plane of the usual shapes.
    constexpr Vector3 kDirections[] = {
        {0.5773f, 0.6231f, 0.5278f}, {-0.7071f, 0.3162f, -0.6325f}, {0.2673f, -0.8018f, 0.5345f}};
    int odd = 0;
    for (const Vector3& d : kDirections) odd += crossings(shape, p, d, step) % 2;
    return odd >= 2;
}

}  // namespace glint
