// Axis-aligned bounding boxes. The default box is empty and absorbs nothing in a union.
#pragma once

#include <algorithm>
#include <optional>
#include <utility>

#include "glint/math/interval.h"
#include "glint/math/ray.h"
#include "glint/math/vector.h"

namespace glint {

struct Bounds3 {
    Point3 min{kInfinity, kInfinity, kInfinity};
    Point3 max{-kInfinity, -kInfinity, -kInfinity};

    static constexpr Bounds3 of(Point3 a, Point3 b) { return {glint::min(a, b), glint::max(a, b)}; }

    constexpr bool is_empty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
    bool is_finite() const { return glint::is_finite(min) && glint::is_finite(max); }
    constexpr Vector3 diagonal() const { return max - min; }
    constexpr Point3 center() const {
        return {(min.x + max.x) / 2, (min.y + max.y) / 2, (min.z + max.z) / 2};
    }
    constexpr bool contains(Point3 p) const {
        return p.x >= min.x && p.x <= max.x && p.y >= min.y && p.y <= max.y && p.z >= min.z &&
               p.z <= max.z;
    }
    constexpr float surface_area() const {
        if (is_empty()) return 0;
        const Vector3 d = diagonal();
        return 2 * (d.x * d.y + d.y * d.z + d.z * d.x);
    }
};

constexpr Bounds3 merge(Bounds3 b, Point3 p) { return {min(b.min, p), max(b.max, p)}; }
constexpr Bounds3 merge(Bounds3 a, Bounds3 b) { return {min(a.min, b.min), max(a.max, b.max)}; }
// The part two boxes share: empty when they do not meet.
constexpr Bounds3 overlap(Bounds3 a, Bounds3 b) { return {max(a.min, b.min), min(a.max, b.max)}; }

// Slab test (Kay and Kajiya 1986): the sub-interval of t_range inside the box, if any.
// Division by a zero direction component gives +-inf, which the comparisons handle.
inline std::optional<Interval> intersect_slabs(const Bounds3& b, const Ray& ray, Interval t_range) {
    for (int axis = 0; axis < 3; ++axis) {
        const float inv = 1 / ray.direction[axis];
        float t_near = (b.min[axis] - ray.origin[axis]) * inv;
        float t_far = (b.max[axis] - ray.origin[axis]) * inv;
        if (t_near > t_far) std::swap(t_near, t_far);
        // NaN (origin on a slab plane, direction parallel) keeps the old bound.
        t_range.min = t_near > t_range.min ? t_near : t_range.min;
        t_range.max = t_far < t_range.max ? t_far : t_range.max;
        if (t_range.min > t_range.max) return std::nullopt;
    }
    return t_range;
}

}  // namespace glint
