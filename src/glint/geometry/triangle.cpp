// A single triangle: bounds, the watertight intersection test, and its surface point.
#include "glint/geometry/triangle.h"

#include <cmath>

#include "glint/geometry/triangle_derivatives.h"
#include "glint/geometry/watertight_triangle.h"
#include "glint/sampling/warp.h"

namespace glint {

Bounds3 Triangle::bounds() const {
    return merge(Bounds3::of(vertices[0], vertices[1]), vertices[2]);
}

std::optional<ShapeHit> intersect_triangle(Point3 v0, Point3 v1, Point3 v2, const Ray& ray,
                                           Interval t_range) {
    return intersect_watertight(v0, v1, v2, ray, t_range);
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
    const UvDerivatives dp = uv_derivatives(
        {to_vector(vertices[0]), to_vector(vertices[1]), to_vector(vertices[2])}, uvs);
    sp.dpdu = dp.du;
    sp.dpdv = dp.dv;
    sp.has_derivatives = true;
    return sp;
}

float double_area(const Triangle& triangle) {
    const auto& v = triangle.vertices;
    return length(cross(v[1] - v[0], v[2] - v[0]));
}

float Triangle::area() const { return 0.5f * double_area(*this); }

SurfaceSample Triangle::sample(Point2 u) const {
    const auto& [v0, v1, v2] = vertices;
    const Point2 b = sample_uniform_triangle(u);
    return {v0 + (v1 - v0) * b.y + (v2 - v0) * (1 - b.x - b.y),
            Normal3(normalize(cross(v1 - v0, v2 - v0))), 1 / area()};
}

}  // namespace glint
