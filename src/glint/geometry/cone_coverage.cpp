// Coverage by projection: seen from the apex, each shape's outline is drawn on the plane one unit
// along the axis, where the cone is a disk of radius `spread`, and the two areas are compared.
#include "glint/geometry/cone_coverage.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "glint/geometry/axis_frame.h"
#include "glint/geometry/shape.h"
#include "glint/math/constants.h"

namespace glint {

namespace {

float cross2(Point2 a, Point2 b) { return a.x * b.y - a.y * b.x; }
float dot2(Point2 a, Point2 b) { return a.x * b.x + a.y * b.y; }

// The signed area the disk of radius r about the origin shares with the triangle (origin, a, b).
float disk_triangle_overlap(Point2 a, Point2 b, float r) {
    const float r2 = r * r;
    const Point2 d{b.x - a.x, b.y - a.y};
    // |a + t d|^2 = r^2 where the segment crosses the circle.
    const float qa = dot2(d, d), qb = 2 * dot2(a, d), qc = dot2(a, a) - r2;
    float cuts[4] = {0, 0, 0, 1};
    int n = 1;
    const float disc = qb * qb - 4 * qa * qc;
    if (qa > 0 && disc > 0) {
        const float root = std::sqrt(disc);
        for (const float t : {(-qb - root) / (2 * qa), (-qb + root) / (2 * qa)})
            if (t > 0 && t < 1) cuts[n++] = t;
    }
    cuts[n++] = 1;
    float area = 0;
    for (int i = 0; i + 1 < n; ++i) {
        const float t0 = cuts[i], t1 = cuts[i + 1];
        const Point2 p{a.x + t0 * d.x, a.y + t0 * d.y}, q{a.x + t1 * d.x, a.y + t1 * d.y};
        const Point2 mid{(p.x + q.x) / 2, (p.y + q.y) / 2};
        if (dot2(mid, mid) <= r2)
            area += cross2(p, q) / 2;  // inside: the triangle itself
        else
            area += r2 / 2 * std::atan2(cross2(p, q), dot2(p, q));  // outside: the sector
    }
    return area;
}

// The cone's frame: two axes across it and the axis.
struct ConeFrame {
    Vector3 s, t, axis;
    Point3 apex;
    Vector3 local(Point3 p) const {
        const Vector3 v = p - apex;
        return {dot(v, s), dot(v, t), dot(v, axis)};
    }
    Vector3 world(Point2 on_unit_plane) const {
        return normalize(s * on_unit_plane.x + t * on_unit_plane.y + axis);
    }
};
ConeFrame frame_of(const RayCone& cone) {
    ConeFrame f;
    orthonormal_basis(cone.axis, f.s, f.t);
    f.axis = cone.axis;
    f.apex = cone.apex;
    return f;
}

// A point of the polygon nearest the origin, nudged a little towards its inside.
Point2 nearest_inside(std::span<const Point2> polygon, float r) {
    // Inside already: the origin itself.
    if (disk_polygon_overlap(polygon, 1e-6f * r) != 0) return {0, 0};
    Point2 best{};
    float best_d2 = kInfinity;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const Point2 a = polygon[i], b = polygon[(i + 1) % polygon.size()];
        const Point2 d{b.x - a.x, b.y - a.y};
        const float len2 = dot2(d, d);
        const float t = len2 > 0 ? std::clamp(-dot2(a, d) / len2, 0.0f, 1.0f) : 0;
        const Point2 p{a.x + t * d.x, a.y + t * d.y};
        if (const float d2 = dot2(p, p); d2 < best_d2) {
            best_d2 = d2;
            best = p;
        }
    }
    Point2 centroid{};
    for (const Point2 p : polygon) centroid = {centroid.x + p.x, centroid.y + p.y};
    centroid = {centroid.x / float(polygon.size()), centroid.y / float(polygon.size())};
    constexpr float kNudge = 0.01f;
    return {best.x + (centroid.x - best.x) * kNudge, best.y + (centroid.y - best.y) * kNudge};
}

}  // namespace

bool has_cone_test(const Shape& shape) {
    return std::holds_alternative<Sphere>(shape) || std::holds_alternative<Plane>(shape) ||
           std::holds_alternative<Polygon>(shape) || std::holds_alternative<Triangle>(shape) ||
           std::holds_alternative<Disk>(shape);
}

float disk_polygon_overlap(std::span<const Point2> polygon, float r) {
    float area = 0;
    for (std::size_t i = 0; i < polygon.size(); ++i)
        area += disk_triangle_overlap(polygon[i], polygon[(i + 1) % polygon.size()], r);
    return std::abs(area);
}

float disk_disk_overlap(float a, float b, float d) {
    if (d >= a + b) return 0;
    if (d <= std::abs(a - b)) return kPi * std::min(a, b) * std::min(a, b);
    // Two circular segments, each cut by the chord through the circles' crossings.
    const float ca = std::clamp((d * d + a * a - b * b) / (2 * d * a), -1.0f, 1.0f);
    const float cb = std::clamp((d * d + b * b - a * a) / (2 * d * b), -1.0f, 1.0f);
    const float alpha = std::acos(ca), beta = std::acos(cb);
    return a * a * (alpha - std::sin(2 * alpha) / 2) + b * b * (beta - std::sin(2 * beta) / 2);
}

std::optional<ConeCoverage> cone_coverage(const RayCone& cone, const Sphere& sphere) {
    // Angles from the apex: the cone's half-angle, the sphere's angular radius, and the angle
    // between the axis and the sphere's centre; the two round outlines overlap as disks do
    // (exact for small angles, Amanatides' own approximation).
    const Vector3 to_center = sphere.center - cone.apex;
    const float distance = length(to_center);
    const float alpha = std::atan(cone.spread);
    if (distance <= sphere.radius) return ConeCoverage{1, 0, cone.axis};  // the apex is inside
    const float beta = std::asin(sphere.radius / distance);
    const Vector3 c = to_center / distance;
    const float theta = std::acos(std::clamp(dot(c, cone.axis), -1.0f, 1.0f));
    const float shared = disk_disk_overlap(alpha, beta, theta);
    if (!(shared > 0)) return std::nullopt;
    const float fraction = std::min(shared / (kPi * alpha * alpha), 1.0f);
    // The direction of the sphere nearest the axis: the axis itself when it meets the sphere,
    // else turned from the centre towards the axis to just inside the outline.
    Vector3 toward = cone.axis;
    if (theta > beta) {
        const Vector3 across = cone.axis - c * dot(cone.axis, c);
        const float turn = beta * 0.99f;
        toward = length_squared(across) > 0
                     ? normalize(c * std::cos(turn) + normalize(across) * std::sin(turn))
                     : c;
    }
    return ConeCoverage{fraction, distance - sphere.radius, toward};
}

std::optional<ConeCoverage> cone_coverage(const RayCone& cone, const Plane& plane) {
    // Seen from the apex the plane fills a half-plane of directions, bounded by its horizon:
    // those w with sign(h) (w.N) < 0, h the apex's height over the plane.
    const ConeFrame f = frame_of(cone);
    const float h = dot(plane.normal, cone.apex - plane.point);
    if (h == 0) return std::nullopt;
    const Vector3 n = f.local(cone.apex + to_vector(plane.normal));  // N in the cone's frame
    const float sign = h > 0 ? 1.0f : -1.0f;
    // On the unit plane, w = (x, y, 1): sign (n.x x + n.y y + n.z) < 0 is a half-plane whose
    // edge lies d = sign n.z / |n.xy| from the origin, on the far side from (n.x, n.y).
    const float across = std::hypot(n.x, n.y);
    const float r = cone.spread;
    float fraction;
    Point2 nearest{0, 0};
    if (across < 1e-12f) {
        fraction = sign * n.z < 0 ? 1.0f : 0.0f;
    } else {
        const float d =
            -sign * n.z / across;  // the covered side: x.u <= d, u = sign (n.x, n.y)/|.|
        if (d <= -r) return std::nullopt;
        if (d >= r) {
            fraction = 1;
        } else {
            // The circular segment beyond the chord at distance -d.
            const float c = std::acos(std::clamp(-d / r, -1.0f, 1.0f));
            const float segment = r * r * (c - std::sin(2 * c) / 2);
            fraction = segment / (kPi * r * r);
        }
        if (d <= 0) {  // the axis misses the plane, or grazes it at the horizon
            const Point2 u{sign * n.x / across, sign * n.y / across};
            const float step = d - 0.01f * r;  // just inside the covered side
            nearest = {u.x * step, u.y * step};
        }
    }
    if (!(fraction > 0)) return std::nullopt;
    const Vector3 toward = f.world(nearest);
    const float along = dot(toward, to_vector(plane.normal));
    const float t = along != 0 ? -h / along : kInfinity;
    return ConeCoverage{fraction, std::max(t * dot(toward, cone.axis), 0.0f), toward};
}

std::optional<ConeCoverage> cone_coverage(const RayCone& cone, std::span<const Point3> corners) {
    const ConeFrame f = frame_of(cone);
    // The corners in the cone's frame, clipped to in front of the apex.
    constexpr float kNear = 1e-6f;
    // Scratch kept by each thread: a cone tracer asks this of every polygon for every cone.
    thread_local std::vector<Vector3> local;
    thread_local std::vector<Point2> projected;
    local.clear();
    projected.clear();
    for (std::size_t i = 0; i < corners.size(); ++i) {
        const Vector3 a = f.local(corners[i]), b = f.local(corners[(i + 1) % corners.size()]);
        if (a.z >= kNear) local.push_back(a);
        if ((a.z >= kNear) != (b.z >= kNear)) {
            const float s = (kNear - a.z) / (b.z - a.z);
            local.push_back(a + (b - a) * s);
        }
    }
    if (local.size() < 3) return std::nullopt;
    float nearest_z = kInfinity;
    for (const Vector3& v : local) {
        projected.push_back({v.x / v.z, v.y / v.z});
        nearest_z = std::min(nearest_z, v.z);
    }
    const float r = cone.spread;
    const float fraction = std::min(disk_polygon_overlap(projected, r) / (kPi * r * r), 1.0f);
    if (!(fraction > 1e-7f)) return std::nullopt;
    const Point2 inside = nearest_inside(projected, r);
    const Vector3 toward = f.world(inside);
    // The depth of the polygon's plane along the axis-near direction.
    const Vector3 e1 = local[1] - local[0], e2 = local[2] - local[0];
    const Vector3 n = cross(e1, e2);
    const Vector3 w{inside.x, inside.y, 1};
    const float along = dot(n, w);
    const float depth = along != 0 ? dot(n, local[0]) / along : nearest_z;
    return ConeCoverage{fraction, std::max(depth, 0.0f), toward};
}

std::optional<ConeCoverage> cone_coverage(const RayCone& cone, const Disk& disk) {
    const Vector3 n = normalize(to_vector(disk.normal));
    const AxisFrame frame = axis_frame(n);
    auto outline = [&](float radius) {
        std::array<Point3, kDiskSides> corners;
        for (int i = 0; i < kDiskSides; ++i) {
            const float phi = 2 * kPi * float(i) / kDiskSides;
            corners[std::size_t(i)] =
                disk.center + (frame.x * std::cos(phi) + frame.z * std::sin(phi)) * radius;
        }
        return corners;
    };
    auto outer = cone_coverage(cone, outline(disk.radius));
    if (!outer || disk.inner_radius <= 0) return outer;
    // A ring: what the hole covers is taken away; the direction to shade must miss the hole.
    const auto hole = cone_coverage(cone, outline(disk.inner_radius));
    if (!hole) return outer;
    outer->fraction -= hole->fraction;
    if (!(outer->fraction > 1e-7f)) return std::nullopt;
    const Vector3 from_center =
        outer->toward * outer->depth / dot(outer->toward, cone.axis) + (cone.apex - disk.center);
    if (length(from_center - n * dot(n, from_center)) < disk.inner_radius) {
        // Just outside the hole, on the side nearest the axis's point.
        Vector3 out = from_center - n * dot(n, from_center);
        out = length_squared(out) > 0 ? normalize(out) : frame.x;
        const Point3 q =
            disk.center + out * (disk.inner_radius + 0.01f * (disk.radius - disk.inner_radius));
        outer->toward = normalize(q - cone.apex);
    }
    return outer;
}

}  // namespace glint
