#include "glint/geometry/triangle.h"

#include <cmath>

namespace glint {

Bounds3 Triangle::bounds() const {
    return merge(Bounds3::of(vertices[0], vertices[1]), vertices[2]);
}

std::optional<ShapeHit> intersect_triangle(Point3 v0, Point3 v1, Point3 v2, const Ray& ray,
                                           Interval t_range) {
    const Vector3 e1 = v1 - v0;
    const Vector3 e2 = v2 - v0;
    const Vector3 p = cross(ray.direction, e2);
    const float det = dot(e1, p);
    if (det == 0 || !std::isfinite(det)) return std::nullopt;  // parallel or degenerate
    const float inv_det = 1 / det;
    const Vector3 s = ray.origin - v0;
    const float b1 = dot(s, p) * inv_det;
    if (b1 < 0 || b1 > 1) return std::nullopt;
    const Vector3 q = cross(s, e1);
    const float b2 = dot(ray.direction, q) * inv_det;
    if (b2 < 0 || b1 + b2 > 1) return std::nullopt;
    const float t = dot(e2, q) * inv_det;
    if (!t_range.contains(t)) return std::nullopt;
    return ShapeHit{t, b1, b2};
}

std::optional<ShapeHit> Triangle::intersect(const Ray& ray, Interval t_range) const {
    return intersect_triangle(vertices[0], vertices[1], vertices[2], ray, t_range);
}

SurfacePoint Triangle::surface_at(const Ray&, const ShapeHit& hit) const {
    const float b0 = 1 - hit.u - hit.v;
    SurfacePoint sp;
    // The barycentric point lies exactly in the triangle's plane, unlike origin + t * direction.
    sp.p = to_point(to_vector(vertices[0]) * b0 + to_vector(vertices[1]) * hit.u +
                    to_vector(vertices[2]) * hit.v);
    sp.normal = Normal3(normalize(cross(vertices[1] - vertices[0], vertices[2] - vertices[0])));
    sp.shading_normal = sp.normal;
    sp.uv = {b0 * uvs[0].x + hit.u * uvs[1].x + hit.v * uvs[2].x,
             b0 * uvs[0].y + hit.u * uvs[1].y + hit.v * uvs[2].y};
    return sp;
}

float double_area(const Triangle& triangle) {
    const auto& v = triangle.vertices;
    return length(cross(v[1] - v[0], v[2] - v[0]));
}

}  // namespace glint
