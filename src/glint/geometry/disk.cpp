// The disk's plane hit (in double, near the centre) and radius test, its polar uv, and the tight
// bounds of a tilted disk that the caps of cylinders and cones share.
#include "glint/geometry/disk.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "glint/geometry/axis_frame.h"
#include "glint/geometry/near_ray.h"
#include "glint/math/constants.h"
#include "glint/sampling/warp.h"

namespace glint {

Bounds3 disk_bounds(Point3 center, Vector3 normal, float radius) {
    const float inv_length = 1 / length(normal);
    const Vector3 n2{normal.x * normal.x, normal.y * normal.y, normal.z * normal.z};
    // A relative margin of a few ulps covers the rounding of the square roots.
    const float r = radius * inv_length * (1 + 1e-6f);
    const Vector3 extent{r * std::sqrt(n2.y + n2.z), r * std::sqrt(n2.x + n2.z),
                         r * std::sqrt(n2.x + n2.y)};
    return {center - extent, center + extent};
}

Bounds3 Disk::bounds() const { return disk_bounds(center, to_vector(normal), radius); }

std::optional<ShapeHit> Disk::intersect(const Ray& ray, Interval t_range) const {
    const NearRay near = near_ray(ray, Vector3d(center));
    const Vector3d n(to_vector(normal));
    const double n_dot_r = dot(n, near.direction);
    if (n_dot_r == 0) return std::nullopt;  // parallel to the disk's plane
    const double s = -dot(n, near.origin) / n_dot_r;
    const auto t = static_cast<float>(near.t_shift + s);
    if (!t_range.contains(t)) return std::nullopt;  // also rejects NaN
    const Vector3d in_plane = near.origin + near.direction * s;
    const double r2 = dot(in_plane, in_plane);
    if (r2 > double{radius} * radius || r2 < double{inner_radius} * inner_radius) {
        return std::nullopt;
    }
    return ShapeHit{t};
}

SurfacePoint Disk::surface_at(const Ray& ray, const ShapeHit& hit) const {
    const Vector3 n = normalize(to_vector(normal));
    const Vector3 offset = ray.at(hit.t) - center;
    // Remove the error of t along the normal so that the point lies in the disk's plane.
    const Vector3 in_plane = offset - n * dot(n, offset);
    SurfacePoint sp;
    sp.p = center + in_plane;
    sp.normal = sp.shading_normal = Normal3(n);
    const float rho = length(in_plane);
    const AxisFrame frame = axis_frame(n);
    sp.uv = {angle_around(frame, in_plane),
             std::clamp((rho - inner_radius) / (radius - inner_radius), 0.0f, 1.0f)};
    // in_plane = rho (cos(phi) x - sin(phi) z) with phi = 2 pi u, rho from v.
    sp.dpdu = (frame.x * dot(in_plane, frame.z) - frame.z * dot(in_plane, frame.x)) * (2 * kPi);
    sp.dpdv = in_plane * ((radius - inner_radius) / std::max(rho, 1e-12f));
    sp.has_derivatives = true;
    return sp;
}

std::string describe_problem(const Disk& disk) {
    std::ostringstream out;
    if (!is_finite(disk.center)) {
        out << "disk center must be finite";
    } else if (!is_finite(to_vector(disk.normal)) || length_squared(to_vector(disk.normal)) == 0) {
        out << "disk normal must be a finite, non-zero direction";
    } else if (!(disk.radius > 0) || !std::isfinite(disk.radius)) {
        out << "disk radius must be > 0, got " << disk.radius;
    } else if (!(disk.inner_radius >= 0 && disk.inner_radius < disk.radius)) {
        out << "disk inner_radius must be in [0, radius), got " << disk.inner_radius
            << " with radius " << disk.radius;
    }
    return out.str();
}

float Disk::area() const { return kPi * (radius * radius - inner_radius * inner_radius); }

SurfaceSample Disk::sample(Point2 u) const {
    Vector3 s, t;
    orthonormal_basis(to_vector(normal), s, t);
    if (inner_radius == 0) {
        // Shirley and Chiu's concentric map keeps a stratified pattern's strata compact.
        const Point2 q = sample_uniform_disk(u);
        return {center + (s * q.x + t * q.y) * radius, normal, 1 / area()};
    }
    const float r2 =
        inner_radius * inner_radius + u.x * (radius * radius - inner_radius * inner_radius);
    const float r = std::sqrt(r2), phi = 2 * kPi * u.y;
    return {center + (s * std::cos(phi) + t * std::sin(phi)) * r, normal, 1 / area()};
}

}  // namespace glint
